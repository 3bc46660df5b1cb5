// The raster's anti-aliasing (cli/frame_samples): jittered frames of one
// moment, averaged. The jitter is checked against a whole-pixel shift of the
// image, the average against the reference tracer's own pixel samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "sim/water_scene.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;

// The columns dx..width-3+dx (rows dy..height-3+dy) of `image`: with dx = 2,
// what a camera two pixels to the right would see of the frame.
std::vector<float> cropped(const std::vector<float>& image, uint32_t dx, uint32_t dy) {
  std::vector<float> out;
  for (uint32_t y = dy; y < kHeight - 2 + dy; ++y)
    for (uint32_t x = dx; x < kWidth - 2 + dx; ++x)
      for (int c = 0; c < 4; ++c) out.push_back(image[(size_t(y) * kWidth + x) * 4 + c]);
  return out;
}

// Without AO (the reference lights with the unoccluded sky, as the raster
// does without AO) and the caustics (their map's error is measured on its
// own: caustics_reference_test.cpp, and by the last case below).
scene::Scene asTheReference(scene::Scene s) {
  s.ao.enabled = false;
  s.render.caustics = false;
  return s;
}

}  // namespace

class AntialiasingTest : public GpuTest {};

// A sample two pixels right of the centre (down) sees what the pixel two on
// sees: the frame is the centred one moved by two pixels. Moved the other
// way, as a sign error would, the two differ everywhere there is detail. (Two,
// not one: derivatives are taken over 2x2 quads, and the textures filtered
// by them, so a one-pixel move pairs other rows and filters the checker
// slightly otherwise.)
TEST_F(AntialiasingTest, JitterMovesWhereThePixelSamples) {
  const scene::Scene s = asTheReference(scene::defaultScene());
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  const auto centred = renderer.render({.frame = 4}).rgba;
  for (const auto& [dx, dy] : {std::pair{2u, 0u}, std::pair{0u, 2u}}) {
    const auto moved = renderer.render({.frame = 4, .pixelOffset = glm::vec2(float(dx), float(dy))}).rgba;
    const auto right = render::tonemappedError(cropped(moved, 0, 0), cropped(centred, dx, dy), s.render.exposure);
    const auto wrong = render::tonemappedError(cropped(moved, dx, dy), cropped(centred, 0, 0), s.render.exposure);
    std::printf("offset (%u, %u): RMSE %.5f against the frame moved by it, %.5f moved the other way\n", dx, dy,
                right.rmse, wrong.rmse);
    EXPECT_LT(right.rmse, 1e-4);
    EXPECT_GT(wrong.rmse, 10.0 * right.rmse);
  }
}

// The samples draw one moment: the water is stepped once, as by one frame.
TEST_F(AntialiasingTest, TheWaterStepsOnceForAllSamples) {
  const scene::Scene s = scene::defaultScene();
  render::Renderer sampled(ctx(), s, kWidth, kHeight), single(ctx(), s, kWidth, kHeight);
  app::renderSamples(sampled, {.frame = 6}, 4);
  single.render({.frame = 6});
  const sim::WaterState a = sampled.waterState(), b = single.waterState();
  ASSERT_EQ(a.u.size(), b.u.size());
  EXPECT_EQ(std::memcmp(a.u.data(), b.u.data(), a.u.size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(float)), 0);
}

// The same samples give the same bits; one sample is the plain frame.
TEST_F(AntialiasingTest, SamplesAreDeterministicAndOneIsThePlainFrame) {
  const scene::Scene s = scene::defaultScene();
  render::Renderer a(ctx(), s, kWidth, kHeight), b(ctx(), s, kWidth, kHeight), c(ctx(), s, kWidth, kHeight);
  const auto first = app::renderSamples(a, {.frame = 3}, 4).rgba;
  const auto second = app::renderSamples(b, {.frame = 3}, 4).rgba;
  EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(float)), 0);
  const auto one = app::renderSamples(a, {.frame = 3}, 1).rgba;
  const auto plain = c.render({.frame = 3}).rgba;
  EXPECT_EQ(std::memcmp(one.data(), plain.data(), one.size() * sizeof(float)), 0);
  EXPECT_NE(std::memcmp(one.data(), first.data(), one.size() * sizeof(float)), 0);
}

// With a transparent sky the alpha is the share of the pixel's samples that
// hit something: 0 in the sky, 1 on the ground, between along the horizon.
TEST_F(AntialiasingTest, TransparentSkyAlphaIsTheCoveredShare) {
  const scene::Scene s = scene::defaultScene();
  render::Renderer renderer(ctx(), s, kWidth, kHeight, {.aovs = true});
  const auto frame = app::renderSamples(renderer, {.frame = 0, .aovs = true}, 8, true);
  ASSERT_EQ(frame.foreground.size(), frame.rgba.size());
  size_t sky = 0, ground = 0, edge = 0;
  for (size_t p = 0; p < frame.foreground.size() / 4; ++p) {
    const float alpha = frame.foreground[p * 4 + 3];
    ASSERT_GE(alpha, 0.0f);
    ASSERT_LE(alpha, 1.0f);
    if (alpha == 0.0f) {
      ++sky;
      EXPECT_EQ(frame.foreground[p * 4], 0.0f);
    } else if (alpha == 1.0f) {
      ++ground;
      EXPECT_NEAR(frame.foreground[p * 4], frame.rgba[p * 4], 1e-5f * frame.rgba[p * 4]);
    } else {
      ++edge;
      EXPECT_EQ(alpha * 8.0f, std::round(alpha * 8.0f));  // whole samples
    }
  }
  std::printf("sky %zu, covered %zu, partly covered %zu pixels\n", sky, ground, edge);
  EXPECT_GT(sky, 0u);
  EXPECT_GT(ground, 0u);
  EXPECT_GT(edge, kWidth / 2);  // the horizon runs across the frame
}

// Sixteen jittered frames against the reference at 256 rays a pixel, on the
// default scene, a sphere under the water and a glass sphere by the pool.
// What one sample leaves at the silhouettes is most of its error.
TEST_F(AntialiasingTest, SixteenSamplesMeetTheReference) {
  struct Case {
    const char* name;
    scene::Scene scene;
    uint32_t frame;
  };
  scene::Scene under = asTheReference(scene::defaultScene());
  under.spheres.at(0).center = {0.0f, under.water.level - 0.45f, 0.0f};
  under.spheres.at(0).radius = 0.4f;
  scene::Scene glass = asTheReference(scene::defaultScene());
  glass.spheres.at(0).material = "glass";
  glass.spheres.at(0).center = {1.6f, glass.water.level + 0.5f, 0.0f};
  // A sphere's shadow on the ground, and one's falling into the pool with the wall's.
  scene::Scene ground = asTheReference(scene::defaultScene());
  ground.camera.position = {6.0f, 2.5f, 1.5f};
  ground.camera.target = {2.5f, 0.0f, -1.5f};
  ground.spheres.at(0).center = {3.0f, 0.7f, -1.0f};
  ground.spheres.at(0).radius = 0.5f;
  scene::Scene pool = ground;
  pool.camera.position = {4.5f, 3.0f, 2.5f};
  pool.camera.target = {-0.5f, 0.0f, 1.0f};
  pool.spheres.at(0).center = {-0.5f, 0.6f, 2.6f};
  scene::Scene caustics = scene::defaultScene();
  caustics.ao.enabled = false;
  // Where the caustics map once showed a hard band along the near wall.
  scene::Scene underCaustics = under;
  underCaustics.render.caustics = true;
  for (const Case& c :
       {Case{"default scene", asTheReference(scene::defaultScene()), 10}, Case{"submerged sphere", under, 10},
        Case{"glass sphere by the pool", glass, 10}, Case{"a shadow on the ground", ground, 10},
        Case{"a shadow into the pool", pool, 10}, Case{"default scene with its caustics", caustics, 10},
        Case{"submerged sphere with the caustics", underCaustics, 10}}) {
    const sim::WaterState water = sim::simulateWater(ctx(), c.scene, c.frame);
    const auto reference = render::renderReference(c.scene, &water, c.frame, kWidth, kHeight, {.samples = 256});
    render::Renderer renderer(ctx(), c.scene, kWidth, kHeight);
    const auto one = app::renderSamples(renderer, {.frame = c.frame}, 1).rgba;
    const auto sixteen = app::renderSamples(renderer, {.frame = c.frame}, 16).rgba;
    const auto e1 = render::tonemappedError(one, reference.rgba, c.scene.render.exposure);
    const auto e16 = render::tonemappedError(sixteen, reference.rgba, c.scene.render.exposure);
    std::printf("%s, frame %u, %ux%u: tonemapped RMSE %.4f (max %.4f) at 16 samples, %.4f (max %.4f) at 1\n", c.name,
                c.frame, kWidth, kHeight, e16.rmse, e16.maxError, e1.rmse, e1.maxError);
    EXPECT_LT(e16.rmse, 0.01) << c.name;
    EXPECT_LT(e16.rmse, 0.7 * e1.rmse) << c.name;
  }
}

}  // namespace tp::test

namespace tp::test {

// The viewer's morphological filter of the tonemapped frame, against the
// reference tonemapped alike: closer than the frame it filters, and only
// along edges (most pixels keep their bits). Off, the scene has no such pass.
TEST_F(AntialiasingTest, MorphologicalFilterMovesTheFrameTowardsTheReference) {
  // Over the pool, where the silhouettes are.
  scene::Scene glass = asTheReference(overThePool(scene::defaultScene()));
  glass.spheres.at(0).material = "glass";
  glass.spheres.at(0).center = {1.6f, glass.water.level + 0.5f, 0.0f};
  for (const auto& [name, base] : {std::pair{"default scene", asTheReference(overThePool(scene::defaultScene()))},
                                   std::pair{"glass sphere by the pool", glass}}) {
    constexpr uint32_t frame = 10, kWidth = 320, kHeight = 180;
    const sim::WaterState water = sim::simulateWater(ctx(), base, frame);
    const auto reference = render::tonemapToSrgb8(
        render::renderReference(base, &water, frame, kWidth, kHeight, {.samples = 256}).rgba, base.render.exposure);
    scene::Scene filtered = base;
    filtered.render.antialiasing = "morphological";
    render::Renderer plain(ctx(), base, kWidth, kHeight), morphological(ctx(), filtered, kWidth, kHeight);
    const auto before = plain.render({.frame = frame, .hdr = false, .ldr = true});
    const auto after = morphological.render({.frame = frame, .hdr = false, .ldr = true});
    EXPECT_EQ(render::findPass(before.passes, render::passes::kAntialias), nullptr);
    ASSERT_NE(render::findPass(after.passes, render::passes::kAntialias), nullptr);
    std::vector<uint8_t> changed(size_t(kWidth) * kHeight);
    for (size_t p = 0; p < changed.size(); ++p)
      changed[p] = std::memcmp(&after.srgb[p * 4], &before.srgb[p * 4], 4) != 0;
    const auto e0 = render::displayError(before.srgb, reference), e1 = render::displayError(after.srgb, reference);
    const auto c0 = render::displayError(before.srgb, reference, changed);
    const auto c1 = render::displayError(after.srgb, reference, changed);
    std::printf(
        "%s, frame %u, %ux%u: display RMSE %.4f filtered, %.4f not; on the %zu pixels it changed %.4f filtered, "
        "%.4f not\n",
        name, frame, kWidth, kHeight, e1.rmse, e0.rmse, c1.pixels, c1.rmse, c0.rmse);
    EXPECT_GT(c1.pixels, size_t(kWidth));                 // the silhouettes
    EXPECT_LT(c1.pixels, size_t(kWidth * kHeight / 20));  // not the textures
    EXPECT_LT(c1.rmse, 0.9 * c0.rmse) << name;            // measured 0.69 and 0.68 of it
    EXPECT_LT(e1.rmse, e0.rmse) << name;
  }
}

}  // namespace tp::test
