// The pool's walls above the water (the dry band, shared/pool_light.h)
// against the path-traced truth. Below its horizon such a wall sees the
// water and the pool's other walls, not the open ground the sky's SH9
// holds there: the water mirrors a little of the sky and lets the pool's
// dim light out.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/path_tracer.hpp"
#include "render/renderer.hpp"
#include "sim/water_scene.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

class DryBandTest : public GpuTest {};

}  // namespace

// Still water 0.5 m under the rim, plain Lambertian walls of albedo 0.5,
// the sun behind the camera, seen as scenes/glossy.json sees its pool, at
// 160x90: the mean per channel, the raster (16 jittered samples, no AO: the
// truth has none) over the truth (256 paths a pixel), and the RMSE, over
// the pixels whose first surface is a wall above the water (2 cm and more
// from the rim and the water), and over the water's within 0.6 m of the
// walls, through which the pool is seen where the walls above the water
// cut its sky. Measured: the walls 0.982, 0.983, 0.984 (RMSE 0.0164), the
// pool by them 0.969, 0.990, 0.992 (0.0207). With the open sky's SH9 on the
// walls, as it was, the walls 1.234, 1.059, 0.909 (0.0485): the ground's
// light below their horizon where the truth's see the water's blue. With
// the walls above the water dark in the pool's bake, as they were, the pool
// by them 0.915, 0.912, 0.915 (0.0294).
TEST_F(DryBandTest, TheWallsAboveTheWaterMatchTheTruth) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  s.water.level = -0.5f;
  s.spheres.clear();
  s.boxes.clear();
  s.ao.enabled = false;
  s.pool.wallPattern = "plain";
  s.pool.wallAlbedo = glm::vec3(0.5f);
  s.pool.wallSpecular = 0.0f;
  s.sky.sunElevationDegrees = 35.0f;
  s.sky.sunAzimuthDegrees = 200.0f;
  s = asGlossySeesThePool(s);
  const sim::WaterState water = sim::simulateWater(ctx(), s, 0);
  const auto truth = render::renderPathTraced(s, &water, 0, width, height, {.samples = 256}).frame;
  render::Renderer renderer(ctx(), s, width, height);
  const auto raster = app::renderSamples(renderer, {.frame = 0}, 16).rgba;
  const float half = 0.5f * s.water.extent, margin = 0.02f;
  // The mean per channel over `mask`, raster over truth, and the RMSE there.
  auto compare = [&](const char* name, const std::vector<uint8_t>& mask, size_t least) {
    const std::array<double, 3> ratio = render::meanRatio(raster, truth.rgba, mask);
    const auto e = render::tonemappedError(raster, truth.rgba, s.render.exposure, mask);
    std::printf("%s: %zu pixels; raster over truth %.3f %.3f %.3f; RMSE %.4f\n", name, e.pixels, ratio[0], ratio[1],
                ratio[2], e.rmse);
    ASSERT_GT(e.pixels, least) << name;
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.05) << name << " channel " << c;
  };
  const std::vector<uint8_t> walls = wallsAboveTheWater(truth.position, s, margin);
  std::vector<uint8_t> floor(walls.size(), 0);
  for (size_t k = 0; k < walls.size(); ++k) {
    const float x = truth.position[k * 4], y = truth.position[k * 4 + 1], z = truth.position[k * 4 + 2];
    const float fromWall = half - std::max(std::abs(x), std::abs(z));
    // The first surface the truth records is the water's: the pool seen
    // through it by the walls, where the walls above the water cut the sky.
    floor[k] = fromWall > margin && fromWall < 0.6f && std::abs(y - s.water.level) < 0.01f;
  }
  compare("the walls above the water", walls, 500);
  compare("the pool by the walls", floor, 300);
}

}  // namespace tp::test
