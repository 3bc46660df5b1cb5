// Light scattered in the water as the raster draws it (the closed form of
// shared/water_scattering.h) against the reference, which samples the same
// integral along its own rays with a shadow ray at each point. What the
// scattering adds to a frame is isolated as the frame with it less the frame
// without, on both sides.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "sim/water_scene.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90, kFrame = 10;
constexpr uint32_t kRasterSamples = 16, kReferenceSamples = 64;

// Without AO, which the reference leaves out, and the caustics, measured on
// their own (caustics_reference_test.cpp).
scene::Scene asTheReference(scene::Scene s) {
  s.ao.enabled = false;
  s.render.caustics = false;
  return s;
}

// The camera under the surface looking across the pool at a sphere and a
// box, as scenes/underwater.json does.
scene::Scene underTheSurface() {
  scene::Scene s = asTheReference(scene::defaultScene());
  s.camera.position = {-1.4f, -0.75f, 1.5f};
  s.camera.target = {0.9f, -0.2f, -0.7f};
  s.camera.fovYDegrees = 70.0f;
  s.spheres.at(0).center = {0.6f, -0.8f, -0.6f};
  s.spheres.at(0).radius = 0.35f;
  s.boxes = {{.center = {-0.6f, -0.9f, -1.0f}, .size = {0.6f, 0.6f, 0.6f}, .yawDegrees = 30.0f}};
  return s;
}

scene::Scene scattering(scene::Scene s) {
  s.water.scattering = {0.08f, 0.12f, 0.14f};
  s.water.scatteringAnisotropy = 0.7f;
  return s;
}

struct Pair {
  std::vector<float> raster, reference;
};

Pair render(const gpu::Context& ctx, const scene::Scene& s) {
  const sim::WaterState water = sim::simulateWater(ctx, s, kFrame);
  render::Renderer renderer(ctx, s, kWidth, kHeight);
  return {app::renderSamples(renderer, {.frame = kFrame}, kRasterSamples).rgba,
          render::renderReference(s, &water, kFrame, kWidth, kHeight, {.samples = kReferenceSamples}).rgba};
}

// ||a - b|| / ||b|| over the RGB channels of two linear images.
double relativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double diff = 0.0, norm = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    if (k % 4 == 3) continue;
    diff += (double(a[k]) - b[k]) * (double(a[k]) - b[k]);
    norm += double(b[k]) * b[k];
  }
  return std::sqrt(diff / norm);
}

std::vector<float> minus(const std::vector<float>& a, const std::vector<float>& b) {
  std::vector<float> d(a.size());
  for (size_t k = 0; k < a.size(); ++k) d[k] = a[k] - b[k];
  return d;
}

}  // namespace

class WaterScatteringGpuTest : public GpuTest {};

// Under the surface and from above it: what the scattering adds, raster
// against reference, and the whole frame within the raster-against-reference
// bound. Without the sun's shadows the two compute one integral (the raster
// in closed form, the reference by sampling); with them, the shafts behind
// the sphere, the box and the walls, the reference shadowing each of its
// points by a ray, the raster at the middles of water.scattering_shadow_pieces (4) pieces
// of the path by the analytic casts: a looser bound.
TEST_F(WaterScatteringGpuTest, WhatTheWaterScattersMatchesTheReference) {
  struct Case {
    const char* name;
    scene::Scene scene;
    double addedBound;
  };
  const scene::Scene under = underTheSurface(), above = asTheReference(overThePool(scene::defaultScene()));
  scene::Scene underNoShadows = under, aboveNoShadows = above;
  underNoShadows.render.shadows = aboveNoShadows.render.shadows = false;
  for (const Case& c : {Case{"under the surface, no shadows", underNoShadows, 0.03},
                        Case{"from above, no shadows", aboveNoShadows, 0.03},
                        Case{"under the surface, shadows", under, 0.04}, Case{"from above, shadows", above, 0.04}}) {
    const Pair clear = render(ctx(), c.scene), scattered = render(ctx(), scattering(c.scene));
    const auto addedRaster = minus(scattered.raster, clear.raster);
    const auto addedReference = minus(scattered.reference, clear.reference);
    const double added = relativeDifference(addedRaster, addedReference);
    const auto frame = render::tonemappedError(scattered.raster, scattered.reference, c.scene.render.exposure);
    const auto before = render::tonemappedError(clear.raster, clear.reference, c.scene.render.exposure);
    const auto change = render::tonemappedError(scattered.raster, clear.raster, c.scene.render.exposure);
    std::printf(
        "%s: what the scattering adds differs from the reference's by %.4f of it; frame RMSE %.4f against the "
        "reference (%.4f without scattering); the scattering changes the frame by %.4f\n",
        c.name, added, frame.rmse, before.rmse, change.rmse);
    EXPECT_LT(added, c.addedBound) << c.name;
    EXPECT_LT(frame.rmse, 0.01) << c.name;
    EXPECT_GT(change.rmse, 0.005) << c.name;  // the scattering is seen
  }
}

}  // namespace tp::test
