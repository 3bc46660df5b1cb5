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
#include "reference/path_tracer.hpp"
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
scene::Scene underTheSurface(scene::Scene s) {
  s.camera.position = {-1.4f, -0.75f, 1.5f};
  s.camera.target = {0.9f, -0.2f, -0.7f};
  s.camera.fovYDegrees = 70.0f;
  s.spheres.at(0).center = {0.6f, -0.8f, -0.6f};
  s.spheres.at(0).radius = 0.35f;
  s.boxes = {{.center = {-0.6f, -0.9f, -1.0f}, .size = {0.6f, 0.6f, 0.6f}, .yawDegrees = 30.0f}};
  return s;
}
scene::Scene underTheSurface() { return underTheSurface(asTheReference(scene::defaultScene())); }

scene::Scene scattering(scene::Scene s, float times = 1.0f) {
  s.water.scattering = times * glm::vec3(0.08f, 0.12f, 0.14f);
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

// Pixels a side of the blocks relativeDifference sums: the reference's
// noise, one point of each path's water sampled, averages out over them
// where the scattering's net change of a pixel is small (seen from above,
// the light it turns stays in the pool, lighting the floor).
constexpr uint32_t kBlock = 8;

// ||A - B|| / ||B|| over the RGB channels of two linear images' sums over
// kBlock x kBlock pixels.
double relativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
  const uint32_t across = kWidth / kBlock, down = (kHeight + kBlock - 1) / kBlock;
  std::vector<double> sumA(size_t(across) * down * 3, 0.0), sumB(sumA.size(), 0.0);
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      for (uint32_t c = 0; c < 3; ++c) {
        const size_t pixel = (size_t(y) * kWidth + x) * 4 + c, block = ((y / kBlock) * across + x / kBlock) * 3 + c;
        sumA[block] += a[pixel];
        sumB[block] += b[pixel];
      }
    }
  }
  double diff = 0.0, norm = 0.0;
  for (size_t k = 0; k < sumA.size(); ++k) {
    diff += (sumA[k] - sumB[k]) * (sumA[k] - sumB[k]);
    norm += sumB[k] * sumB[k];
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
    float times;  // the scattering's coefficients times this
  };
  const scene::Scene under = underTheSurface(), above = asTheReference(overThePool(scene::defaultScene()));
  scene::Scene underNoShadows = under, aboveNoShadows = above;
  underNoShadows.render.shadows = aboveNoShadows.render.shadows = false;
  // Seen from above the scattering's net change of the frame is small: the
  // light it turns away from a ray stays in the pool and lights the floor.
  // Four times the coefficients there make it seen.
  for (const Case& c :
       {Case{"under the surface, no shadows", underNoShadows, 0.03, 1.0f},
        Case{"from above, no shadows", aboveNoShadows, 0.03, 4.0f},
        Case{"under the surface, shadows", under, 0.04, 1.0f}, Case{"from above, shadows", above, 0.04, 4.0f}}) {
    const Pair clear = render(ctx(), c.scene), scattered = render(ctx(), scattering(c.scene, c.times));
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

// The haze seen from under the surface against the path-traced truth
// (reference/path_tracer), which follows every path through the water,
// scattered any number of times: the raster's frame as a user renders it
// (16 jittered samples, its AO and caustics) against the mean of two seeds
// of 256 paths, in water that scatters and in clear water. The frame's mean
// per channel, raster over truth, against clear water's (0.95, 1.00, 1.00),
// and the tonemapped RMSE against clear water's (0.023). With the sky's beam
// alone for the light the water scatters, and the bake's and the sun's
// light losing the whole extinction, the means were 0.82, 0.65 and 0.58,
// the RMSE 0.121.
TEST_F(WaterScatteringGpuTest, TheHazeUnderTheSurfaceMatchesTheTruth) {
  constexpr uint32_t kTruthPaths = 256;
  const scene::Scene clear = underTheSurface(scene::defaultScene()), hazy = scattering(clear);
  struct Frames {
    std::vector<float> raster, truth;
  };
  auto frames = [&](const scene::Scene& s) {
    const sim::WaterState water = sim::simulateWater(ctx(), s, kFrame);
    render::Renderer renderer(ctx(), s, kWidth, kHeight);
    Frames f{app::renderSamples(renderer, {.frame = kFrame}, kRasterSamples).rgba, {}};
    const auto a = render::renderPathTraced(s, &water, kFrame, kWidth, kHeight, {.samples = kTruthPaths}).frame.rgba;
    const auto b =
        render::renderPathTraced(s, &water, kFrame, kWidth, kHeight, {.samples = kTruthPaths, .seed = 1}).frame.rgba;
    f.truth.resize(a.size());
    for (size_t k = 0; k < a.size(); ++k) f.truth[k] = 0.5f * (a[k] + b[k]);
    return f;
  };
  const Frames without = frames(clear), with = frames(hazy);
  // The frame's sum per channel, raster over truth.
  auto ratio = [](const Frames& f, int c) {
    double raster = 0.0, truth = 0.0;
    for (size_t k = size_t(c); k < f.raster.size(); k += 4) {
      raster += f.raster[k];
      truth += f.truth[k];
    }
    return raster / truth;
  };
  const double hazyError = render::tonemappedError(with.raster, with.truth, hazy.render.exposure).rmse;
  const double clearError = render::tonemappedError(without.raster, without.truth, clear.render.exposure).rmse;
  std::printf(
      "the frame's mean, raster over truth: %.3f %.3f %.3f (%.3f %.3f %.3f in clear water); RMSE %.4f against the "
      "truth (%.4f in clear water)\n",
      ratio(with, 0), ratio(with, 1), ratio(with, 2), ratio(without, 0), ratio(without, 1), ratio(without, 2),
      hazyError, clearError);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio(with, c), ratio(without, c), 0.08) << "channel " << c;
  EXPECT_LT(hazyError, clearError + 0.012);
}

}  // namespace tp::test
