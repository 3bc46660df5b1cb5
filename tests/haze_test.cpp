// Aerial perspective (shared/haze.h, resolve.comp): the GPU pass against the
// shared function applied on the CPU to the frame without it, the raster
// against the reference, and the closed form of the transmittance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_tracer.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "shading/sky_model.hpp"
#include "shared/haze.h"
#include "shared/sky.h"
#include "sim/water_scene.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr float kHazeDistance = 30.0f;

// The default scene with haze, AO and caustics off as the reference has them.
scene::Scene hazyScene() {
  scene::Scene s = scene::defaultScene();
  s.ao.enabled = false;
  s.render.caustics = false;
  s.sky.hazeDistance = kHazeDistance;
  return s;
}

}  // namespace

// exp(-s / D): 1 at the camera, 1/e at D, halving every D ln 2.
TEST(HazeModel, TransmittanceIsTheExponentialOfTheDistance) {
  EXPECT_FLOAT_EQ(shader::hazeTransmittance(0.0f, 30.0f), 1.0f);
  EXPECT_NEAR(shader::hazeTransmittance(30.0f, 30.0f), std::exp(-1.0f), 1e-7f);
  EXPECT_NEAR(shader::hazeTransmittance(30.0f * std::log(2.0f), 30.0f), 0.5f, 1e-6f);
  const glm::vec3 h = shader::hazed(glm::vec3(1.0f), glm::vec3(0.0f), 30.0f, 30.0f);
  EXPECT_NEAR(h.x, std::exp(-1.0f), 1e-7f);
  const glm::vec3 d = shader::hazeHorizonDirection(glm::normalize(glm::vec3(3.0f, -4.0f, 4.0f)));
  EXPECT_NEAR(d.x, 0.6f, 1e-6f);
  EXPECT_EQ(d.y, 0.0f);
  EXPECT_NEAR(d.z, 0.8f, 1e-6f);
}

using HazeTest = GpuTest;

// The pass applies the shared function: the frame with haze is the frame
// without it, faded on the CPU by hazed() with the distance from the
// position AOV and the analytic sky at the horizon. What is left is the sky
// texture's bilinear lookup at the horizon against the analytic sky there.
TEST_F(HazeTest, GpuPassAppliesTheSharedFunction) {
  const scene::Scene s = hazyScene();
  scene::Scene clear = s;
  clear.sky.hazeDistance = 0.0f;
  render::Renderer hazy(ctx(), s, kWidth, kHeight), plain(ctx(), clear, kWidth, kHeight, {.aovs = true});
  const auto withHaze = hazy.render({.frame = 0, .hdr = true});
  const auto without = plain.render({.frame = 0, .hdr = true, .aovs = true});
  ASSERT_NE(render::findPass(withHaze.passes, render::passes::kResolve), nullptr);
  EXPECT_EQ(render::findPass(without.passes, render::passes::kResolve), nullptr);
  const shader::SkyParams sky = render::skyParams(s.sky);
  const glm::vec3 eye = s.camera.position;
  const glm::mat4 ndcToWorld = glm::inverse(without.worldToNDC);
  std::vector<float> expected = without.rgba;
  size_t surfaces = 0, lowerSky = 0;
  for (size_t k = 0; k < size_t(kWidth) * kHeight; ++k) {
    const glm::vec3 p(without.position[k * 4], without.position[k * 4 + 1], without.position[k * 4 + 2]);
    // The pixel's ray, through its centre.
    const glm::vec2 ndc((float(k % kWidth) + 0.5f) / float(kWidth) * 2.0f - 1.0f,
                        (float(k / kWidth) + 0.5f) / float(kHeight) * 2.0f - 1.0f);
    const glm::vec4 far = ndcToWorld * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - eye);
    const glm::vec3 horizon = shader::skyRadiance(sky, shader::hazeHorizonDirection(dir), 1.0f);
    glm::vec3 out(without.rgba[k * 4], without.rgba[k * 4 + 1], without.rgba[k * 4 + 2]);
    if (std::isfinite(without.position[k * 4 + 3])) {
      out = shader::hazed(out, horizon, glm::distance(p, eye), kHazeDistance);
      ++surfaces;
    } else if (dir.y < 0.0f) {
      out = horizon;
      ++lowerSky;
    }
    for (int c = 0; c < 3; ++c) expected[k * 4 + c] = out[c];
  }
  const auto e = render::tonemappedError(withHaze.rgba, expected, s.render.exposure);
  std::printf("haze pass against hazed() on the CPU: %zu surface and %zu lower-sky pixels; RMSE %.5f, max %.5f\n",
              surfaces, lowerSky, e.rmse, e.maxError);
  ASSERT_GT(surfaces, size_t(kWidth * kHeight / 2));
  // Measured 0.0044; the distance taken 10% too long gives 0.0106.
  EXPECT_LT(e.maxError, 0.006);
  // Without the pass the far ground is far off.
  EXPECT_GT(render::tonemappedError(without.rgba, expected, s.render.exposure).maxError, 0.1);
}

// Sixteen jittered frames against the reference's 256 rays a pixel, which
// fades each of its camera rays by the same function: the ground runs into
// the horizon in both.
TEST_F(HazeTest, RasterMatchesTheReference) {
  constexpr uint32_t frame = 10;
  const scene::Scene s = hazyScene();
  scene::Scene clear = s;
  clear.sky.hazeDistance = 0.0f;
  const sim::WaterState water = sim::simulateWater(ctx(), s, frame);
  const auto reference = render::renderReference(s, &water, frame, kWidth, kHeight, {.samples = 256});
  render::Renderer renderer(ctx(), s, kWidth, kHeight), plain(ctx(), clear, kWidth, kHeight);
  const auto hazy = app::renderSamples(renderer, {.frame = frame}, 16).rgba;
  const auto withoutHaze = app::renderSamples(plain, {.frame = frame}, 16).rgba;
  const auto e = render::tonemappedError(hazy, reference.rgba, s.render.exposure);
  const auto off = render::tonemappedError(withoutHaze, reference.rgba, s.render.exposure);
  std::printf("haze %.0f m, frame %u, %ux%u, 16 samples against 256: RMSE %.4f (max %.4f); without the haze %.4f\n",
              kHazeDistance, frame, kWidth, kHeight, e.rmse, e.maxError, off.rmse);
  EXPECT_LT(e.rmse, 0.01);
  EXPECT_GT(off.rmse, 3.0 * e.rmse);
}

// Under the water there is no air between the camera and what it sees: the
// pass changes nothing.
TEST_F(HazeTest, CameraUnderTheWaterSeesNoHaze) {
  scene::Scene s = hazyScene();
  s.camera.position = {-1.4f, -0.75f, 1.5f};
  s.camera.target = {0.9f, -0.2f, -0.7f};
  scene::Scene clear = s;
  clear.sky.hazeDistance = 0.0f;
  render::Renderer hazy(ctx(), s, kWidth, kHeight), plain(ctx(), clear, kWidth, kHeight);
  EXPECT_EQ(hazy.render({.frame = 3}).rgba, plain.render({.frame = 3}).rgba);
}

}  // namespace tp::test
