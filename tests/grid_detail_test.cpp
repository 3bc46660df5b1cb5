// The water's and the floor's grids drawn coarser where a quad would span a
// fraction of a pixel (shading/grid_detail.hpp): the coarser meshes cover the
// same square, the step follows the projected quad's size, and the frames
// drawn with them are as close to the reference as the frames drawn whole.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "shading/grid_detail.hpp"
#include "shading/water_model.hpp"
#include "sim/water_scene.hpp"

namespace tp::test {
namespace {

// The triangles of a strip list (kStripRestart between rows), in grid
// coordinates (vertex k at (k % n, k / n)): their signed areas' sum.
double stripArea(const std::vector<uint32_t>& strips, uint32_t n) {
  double area = 0.0;
  std::vector<uint32_t> row;
  auto close = [&] {
    for (size_t t = 0; t + 2 < row.size(); ++t) {
      const glm::dvec2 a(row[t] % n, row[t] / n), b(row[t + 1] % n, row[t + 1] / n), c(row[t + 2] % n, row[t + 2] / n);
      const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      area += (t % 2 == 0 ? 0.5 : -0.5) * cross;  // a strip's odd triangles are wound the other way
    }
    row.clear();
  };
  for (const uint32_t k : strips) {
    if (k == render::kStripRestart) {
      close();
      continue;
    }
    EXPECT_LT(k, n * n);
    row.push_back(k);
  }
  close();
  return area;
}

}  // namespace

// Every step's mesh covers the whole square once, over the full grid's own
// vertices, its last row and column included where the step does not divide
// the grid; step 1 is the grid as it was.
TEST(GridDetail, CoarserMeshesCoverTheSameSquare) {
  for (const uint32_t n : {5u, 6u, 128u, 129u}) {
    SCOPED_TRACE("n " + std::to_string(n));
    EXPECT_EQ(render::waterGridStrips(n), render::waterGridStrips(n, 1));
    for (const uint32_t step : {1u, 2u, 4u}) {
      const auto strips = render::waterGridStrips(n, step);
      EXPECT_NEAR(std::abs(stripArea(strips, n)), double(n - 1) * (n - 1), 1e-9) << "step " << step;
      const auto list = render::waterGridIndices(n, step);
      double area = 0.0;
      for (size_t t = 0; t < list.size(); t += 3) {
        const glm::dvec2 a(list[t] % n, list[t] / n), b(list[t + 1] % n, list[t + 1] / n),
            c(list[t + 2] % n, list[t + 2] / n);
        area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
      }
      EXPECT_NEAR(area, double(n - 1) * (n - 1), 1e-9) << "step " << step;
      const uint32_t lines = (n - 2) / step + 2;  // 0, step, ... below n - 1, and n - 1
      EXPECT_EQ(list.size(), size_t(lines - 1) * (lines - 1) * 6) << "step " << step;
    }
  }
  EXPECT_THROW(render::waterGridStrips(5, 0), std::invalid_argument);
}

// Straight down on a square of side 2 with 129 vertices a side (128 quads),
// 90 degrees of view over 256 pixels: from h metres its side spans 256 / h
// pixels, a quad 2 / h. A quad may span 2 pixels (kMaxQuadPixels).
TEST(GridDetail, TheStepFollowsTheProjectedQuad) {
  auto stepFrom = [](float h) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, h, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, 0.01f, 100.0f);
    return render::gridStep(projection * view, glm::vec2(256.0f), glm::vec3(0.0f), 2.0f, 129);
  };
  EXPECT_EQ(stepFrom(0.9f), 1u);   // 2.2 pixels a quad
  EXPECT_EQ(stepFrom(1.1f), 1u);   // 1.8: two would span 3.6
  EXPECT_EQ(stepFrom(2.0f), 2u);   // 1.0: two span 2
  EXPECT_EQ(stepFrom(3.0f), 2u);   // 0.67: four would span 2.7
  EXPECT_EQ(stepFrom(4.0f), 4u);   // 0.5: four span 2
  EXPECT_EQ(stepFrom(40.0f), 4u);  // no coarser than four
  // A corner behind the camera: the square may fill the frame.
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0.0f, 0.5f, -1.0f), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.01f, 100.0f);
  EXPECT_EQ(render::gridStep(projection * view, glm::vec2(16.0f), glm::vec3(0.0f), 2.0f, 129), 1u);
}

using GridDetailGpuTest = GpuTest;

// The default scene at the sizes `view --target-fps` goes down to, and the
// wake of scenes/wake.json (the roughest water the scenes have: a sphere
// dragged through it; at 320x180 its camera is close enough for step 1), 16 jittered samples a pixel, with the grids
// drawn coarser and drawn whole, each against the reference's 64 rays a pixel (without AO and caustics, which the
// reference leaves out): over the frame and over the water's pixels.
TEST_F(GridDetailGpuTest, CoarserGridsAreAsCloseToTheReference) {
  struct Case {
    const char* name;
    scene::Scene scene;
    uint32_t frame, width, height;
  };
  const scene::Scene wake = scene::loadSceneFile(std::string(TIDEPOOL_SOURCE_DIR) + "/scenes/wake.json");
  for (Case c : {Case{"default", scene::defaultScene(), 10, 160, 90},
                 Case{"default", scene::defaultScene(), 10, 320, 180}, Case{"wake", wake, 30, 160, 90}}) {
    const std::string name = std::string(c.name) + " " + std::to_string(c.width) + "x" + std::to_string(c.height);
    SCOPED_TRACE(name);
    scene::Scene& s = c.scene;
    s.ao.enabled = false;
    s.render.caustics = false;
    const sim::WaterState water = sim::simulateWater(ctx(), s, c.frame);
    const auto reference = render::renderReference(s, &water, c.frame, c.width, c.height, {.samples = 64});
    render::Renderer aovRenderer(ctx(), s, c.width, c.height, {.aovs = true});
    const auto mask =
        render::waterPixelMask(aovRenderer.render({.frame = c.frame, .hdr = false, .aovs = true}), s.water);
    render::Renderer coarse(ctx(), s, c.width, c.height), whole(ctx(), s, c.width, c.height, {.coarseGrids = false});
    const auto a = app::renderSamples(coarse, {.frame = c.frame}, 16).rgba;
    const auto b = app::renderSamples(whole, {.frame = c.frame}, 16).rgba;
    const auto ea = render::tonemappedError(a, reference.rgba, s.render.exposure);
    const auto eb = render::tonemappedError(b, reference.rgba, s.render.exposure);
    const auto wa = render::tonemappedError(a, reference.rgba, s.render.exposure, mask);
    const auto wb = render::tonemappedError(b, reference.rgba, s.render.exposure, mask);
    const auto between = render::tonemappedError(a, b, s.render.exposure, mask);
    std::printf(
        "%s: coarser grids RMSE %.4f (water %.4f over %zu px), whole %.4f (water %.4f); between them on the "
        "water %.4f\n",
        name.c_str(), ea.rmse, wa.rmse, wa.pixels, eb.rmse, wb.rmse, between.rmse);
    ASSERT_GT(wa.pixels, size_t(c.width * c.height / 20));
    EXPECT_GT(between.rmse, 0.0);  // the coarser grids were drawn
    EXPECT_LT(ea.rmse, eb.rmse * 1.05);
    EXPECT_LT(wa.rmse, wb.rmse * 1.05);
  }
}

}  // namespace tp::test
