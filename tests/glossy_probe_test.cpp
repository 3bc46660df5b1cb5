// A glossy sphere's probe (render/glossy_probes): what the sphere reflects
// against the path-traced truth, and the frame graph's caching of the
// probes' passes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/path_tracer.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "sim/water_scene.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

class GlossyProbeTest : public GpuTest {};

// scenes/glossy.json's white sphere (specular 0.8, roughness 0.3) over the
// still pool, half of it over the water, seen from close by.
scene::Scene glossySphereOverThePool() {
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  s.water.level = -0.5f;
  s.boxes.clear();
  s.ao.enabled = false;  // the truth has none
  s.pool.wallPattern = "plain";
  s.pool.wallAlbedo = glm::vec3(0.5f, 0.55f, 0.6f);
  s.pool.wallSpecular = 0.0f;
  s.sky.sunElevationDegrees = 35.0f;
  s.sky.sunAzimuthDegrees = 200.0f;
  s.spheres.resize(1);
  s.spheres[0] = scene::Sphere{};
  s.spheres[0].center = {0.4f, 0.1f, -0.6f};
  s.spheres[0].radius = 0.45f;
  s.spheres[0].albedo = {0.85f, 0.85f, 0.9f};
  s.spheres[0].specular = 0.8f;
  s.spheres[0].roughness = 0.3f;
  s.camera.position = {1.9f, 0.5f, 0.7f};
  s.camera.target = {0.4f, 0.0f, -0.6f};
  s.camera.fovYDegrees = 40.0f;
  return s;
}

}  // namespace

// The sphere against the truth (256 paths a pixel), the raster at 16
// jittered samples, 160x90, over the pixels whose first surface is the
// sphere: the RMSE and the mean per channel, raster over truth. Its lower
// half mirrors the water, the pool's floor through it and the terrace, its
// upper half the sky. Measured: RMSE 0.0319, means 1.048, 1.028, 1.009
// (what is left is mostly the lobe's shape: the raster's Phong lobe has
// neither GGX's long tails nor its shadowing at grazing angles, so the
// sun's highlight is too small and the rim too bright). With the sky's
// glossy map in place of the probe, as it was, RMSE 0.1176, means 1.045,
// 0.918, 0.849: the lower half mirrored the sky's flat ground colour.
TEST_F(GlossyProbeTest, TheSphereSeesTheSceneAroundIt) {
  constexpr uint32_t width = 160, height = 90;
  const scene::Scene s = glossySphereOverThePool();
  const sim::WaterState water = sim::simulateWater(ctx(), s, 0);
  const auto truth = render::renderPathTraced(s, &water, 0, width, height, {.samples = 256}).frame;
  render::Renderer renderer(ctx(), s, width, height);
  const auto raster = app::renderSamples(renderer, {.frame = 0}, 16).rgba;
  std::vector<uint8_t> sphere(size_t(width) * height, 0);
  const scene::Sphere& ball = s.spheres[0];
  for (size_t k = 0; k < sphere.size(); ++k) {
    const glm::vec3 p(truth.position[k * 4], truth.position[k * 4 + 1], truth.position[k * 4 + 2]);
    sphere[k] = std::isfinite(p.x) && std::abs(glm::distance(p, ball.center) - ball.radius) < 2e-3f;
  }
  const std::array<double, 3> ratio = render::meanRatio(raster, truth.rgba, sphere);
  const auto e = render::tonemappedError(raster, truth.rgba, s.render.exposure, sphere);
  std::printf("the glossy sphere: %zu pixels; raster over truth %.3f %.3f %.3f; RMSE %.4f\n", e.pixels, ratio[0],
              ratio[1], ratio[2], e.rmse);
  ASSERT_GT(e.pixels, size_t(width * height / 10));
  EXPECT_LT(e.rmse, 0.05);
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.07) << "channel " << c;
}

// The walls above the water of scenes/glossy.json (specular 0.3, roughness
// 0.5), its spheres taken out, against the truth as tests/dry_band_test.cpp
// sees them (160x90, 16 jittered samples against 256 paths): across the
// pool they mirror the water and the other walls, not the sky. Measured:
// RMSE 0.0262, means 1.029, 0.977, 0.965; with the sky's glossy map in
// place of the pool's probe, as it was, RMSE 0.0434, means 1.067, 0.905,
// 0.842 (the sky's light where the truth's walls see the water's blue).
TEST_F(GlossyProbeTest, TheWallsAboveTheWaterSeeThePool) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = asGlossySeesThePool(glossySphereOverThePool());
  s.spheres.clear();
  s.pool.wallSpecular = 0.3f;
  s.pool.wallRoughness = 0.5f;
  const sim::WaterState water = sim::simulateWater(ctx(), s, 0);
  const auto truth = render::renderPathTraced(s, &water, 0, width, height, {.samples = 256}).frame;
  render::Renderer renderer(ctx(), s, width, height);
  const auto raster = app::renderSamples(renderer, {.frame = 0}, 16).rgba;
  const std::vector<uint8_t> walls = wallsAboveTheWater(truth.position, s, 0.02f);
  const std::array<double, 3> ratio = render::meanRatio(raster, truth.rgba, walls);
  const auto e = render::tonemappedError(raster, truth.rgba, s.render.exposure, walls);
  std::printf("the glossy walls above the water: %zu pixels; raster over truth %.3f %.3f %.3f; RMSE %.4f\n", e.pixels,
              ratio[0], ratio[1], ratio[2], e.rmse);
  ASSERT_GT(e.pixels, size_t(500));
  EXPECT_LT(e.rmse, 0.035);
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.06) << "channel " << c;
}

// The probes' passes run on the first frame, not again while only the
// camera moves, and again when the sphere moves; each
// frame has the bits of a renderer that runs them every frame. A scene
// without glossy spheres has none.
TEST_F(GlossyProbeTest, ProbesRunAgainOnlyWhenTheSphereOrTheLightMoves) {
  scene::Scene s = glossySphereOverThePool();
  s.sky.textureWidth = 256;
  render::Renderer skipping(ctx(), s, 64, 36);
  render::Renderer everything(ctx(), s, 64, 36, {.skipping = false});
  auto expectProbes = [&](uint32_t frame, bool run, const char* what) {
    const auto a = skipping.render({.frame = frame});
    const auto b = everything.render({.frame = frame});
    EXPECT_EQ(render::findPass(a.passes, render::passes::kGlossyProbes) != nullptr, run) << what;
    EXPECT_EQ(render::findPass(a.passes, render::passes::kGlossyProbePrefilter) != nullptr, run) << what;
    EXPECT_TRUE(render::findPass(b.passes, render::passes::kGlossyProbes)) << what;
    EXPECT_EQ(a.rgba, b.rgba) << what;
  };
  expectProbes(0, true, "the first frame");
  scene::Camera camera = s.camera;
  camera.position.x += 0.3f;
  skipping.setCamera(camera);
  everything.setCamera(camera);
  expectProbes(1, false, "the camera moved");
  skipping.moveSphere(0, s.spheres[0].center + glm::vec3(0.0f, 0.1f, 0.0f));
  everything.moveSphere(0, s.spheres[0].center + glm::vec3(0.0f, 0.1f, 0.0f));
  expectProbes(2, true, "the sphere moved");
  expectProbes(3, false, "nothing moved");
  s.spheres[0].specular = 0.0f;
  render::Renderer matte(ctx(), s, 64, 36, {.skipping = false});
  EXPECT_FALSE(render::findPass(matte.render({.frame = 0}).passes, render::passes::kGlossyProbes));
}

}  // namespace tp::test
