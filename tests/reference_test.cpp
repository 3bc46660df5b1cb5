// The CPU reference (render/reference_tracer) against closed-form answers, and
// the rasterised frame against the reference: the error figures of the
// accurate and apparent refraction modes rest on both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "exact_fresnel.hpp"
#include "gpu_test.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/sky_model.hpp"
#include "shading/water_model.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

// Flat water in a pool whose every surface is black, under a sky of radiance 1
// in every direction: the light leaving the water towards the camera is the
// sky reflected with the Fresnel reflectance of the view ray's angle, and nothing else.
scene::Scene blackPoolUnderWhiteSky() {
  scene::Scene s = checkerScene();
  s.sky.zenith = s.sky.horizon = s.sky.ground = glm::vec3(1.0f);
  s.sky.glow = glm::vec3(0.0f);
  s.sky.sunRadiance = glm::vec3(0.0f);
  s.ground.albedoA = s.ground.albedoB = glm::vec3(0.0f);
  s.pool.wallAlbedo = s.pool.tileAlbedoA = s.pool.tileAlbedoB = glm::vec3(0.0f);
  s.spheres.clear();
  s.water.drops.clear();
  s.camera.position = {0.0f, 3.0f, 1.2f};
  s.camera.target = {0.0f, s.water.level, 0.0f};
  return s;
}

}  // namespace

// The mean ratio per channel counts the masked pixels alone, summed before
// they are divided: red 1 and 3 over 2 and 2 is 1, green 2 and 2 over 2 and
// 4 is 2 / 3, not the mean of the ratios.
TEST(ImageError, MeanRatioSumsTheMaskedPixelsBeforeDividing) {
  const std::vector<float> a = {1, 2, 4, 1, 3, 2, 4, 1, 100, 100, 100, 1};
  const std::vector<float> b = {2, 2, 2, 1, 2, 4, 2, 1, 1, 1, 1, 1};
  const std::vector<uint8_t> mask = {1, 1, 0};
  const std::array<double, 3> r = render::meanRatio(a, b, mask);
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_DOUBLE_EQ(r[1], 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(r[2], 2.0);
}

TEST(ReferenceTest, FlatWaterReflectsTheSkyByFresnelsEquations) {
  const scene::Scene s = blackPoolUnderWhiteSky();
  const sim::WaterState water = sim::flatState(s.water.grid);
  constexpr uint32_t width = 96, height = 64;
  const render::RenderedFrame frame = render::renderReference(s, &water, 0, width, height, {.samples = 1});
  const auto u = render::frameUniforms(s, width, height);
  size_t checked = 0;
  double worst = 0.0, worstSchlick = 0.0;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t k = size_t(y) * width + x;
      const glm::vec3 p(frame.position[k * 4], frame.position[k * 4 + 1], frame.position[k * 4 + 2]);
      // Water far enough from the walls that its reflected ray clears the rim.
      if (std::abs(p.y - s.water.level) > 1e-4f || std::abs(p.x) > 1.5f || std::abs(p.z) > 1.5f) continue;
      const glm::vec3 view = glm::normalize(p - glm::vec3(u.cameraPosition));
      const double cosI = -view.y;
      const double expected = fresnelFromAir(cosI, s.water.ior);
      const double f0 = std::pow((s.water.ior - 1.0) / (s.water.ior + 1.0), 2.0);
      worstSchlick = std::max(worstSchlick, std::abs(f0 + (1.0 - f0) * std::pow(1.0 - cosI, 5.0) - expected));
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(frame.rgba[k * 4 + c]) - expected));
      ++checked;
    }
  }
  std::printf("%zu water pixels, largest error %.2e (Schlick's approximation is off by up to %.2e here)\n", checked,
              worst, worstSchlick);
  ASSERT_GT(checked, size_t(width * height / 4));
  // Float round-off on a reflectance of a few percent; Schlick's curve would fail it.
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(worstSchlick, 1e-3);
}

// Tonemapped RMSE (display units 0..1) of the supersampled raster against the
// reference at 64 samples per pixel, over the frame or a mask of it. Measured
// on lavapipe at 160x90: 0.0029 to 0.0095 in every test below (each prints
// its figures), where the apparent-depth mode, light taking other paths, is
// 0.035 over the frame and 0.097 on the water. (64, not 16: each sample
// sends one shadow ray to a point of the sun's disc, and at 16 the
// penumbrae's noise alone put the water's pixels at 0.0099.)
constexpr double kRasterBound = 0.012;
// The brick walls seen through the water: 0.0065 while the raster showed the
// pool n^2 too bright; 0.0121 since it scales the light by 1 / n^2 and takes
// the sun through the water (docs/accuracy.md). The same joints refracted by
// the waves, now darker, where the display curve is steeper.
constexpr double kBricksThroughWaterBound = 0.015;

class ReferenceRasterTest : public GpuTest {
 protected:
  // The raster at 4x4 samples per pixel (rendered at 4x the size, box
  // filtered), to meet the reference's samples at silhouettes: what differs then
  // is the light's paths, not the sampling. Without AO: the reference lights
  // with the unoccluded sky, as the raster does without it (AO has its own
  // reference, tests/ssao_test.cpp).
  std::vector<float> supersampledRaster(scene::Scene s, uint32_t frame, uint32_t width, uint32_t height,
                                        uint32_t factor = 4) {
    s.ao.enabled = false;
    render::Renderer renderer(ctx(), s, width * factor, height * factor);
    const auto raster = renderer.render({.frame = frame, .hdr = true});
    return render::boxDownsample(raster.rgba, width * factor, height * factor, factor);
  }

  // The reference of a frame of the water (64 samples a pixel), and which of
  // its pixels show the water.
  struct ReferenceWithWater {
    render::RenderedFrame reference;
    std::vector<uint8_t> water;
  };
  ReferenceWithWater referenceWithWater(const scene::Scene& s, uint32_t frame, uint32_t width, uint32_t height) {
    const sim::WaterState water = sim::simulateWater(ctx(), s, frame);
    render::Renderer aovRenderer(ctx(), s, width, height, {.aovs = true});
    return {render::renderReference(s, &water, frame, width, height, {.samples = 64}),
            render::waterPixelMask(aovRenderer.render({.frame = frame, .hdr = false, .aovs = true}), s.water)};
  }
};

TEST_F(ReferenceRasterTest, WithoutWaterRasterAndReferenceAgree) {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;
  constexpr uint32_t width = 160, height = 90;
  const auto raster = supersampledRaster(s, 0, width, height);
  const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 64});
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure);
  std::printf("no water, 160x90: tonemapped RMSE %.4f, max %.4f\n", e.rmse, e.maxError);
  // What is left is the two filters' different samples at silhouettes and the
  // horizon. A camera off by one pixel, or shading that differs, is several
  // times more.
  EXPECT_LT(e.rmse, kRasterBound);
}

TEST_F(ReferenceRasterTest, AccurateRefractionIsCloserToTheReferenceThanApparentDepth) {
  scene::Scene s = overThePool(scene::defaultScene());
  s.render.caustics = false;  // the reference leaves them out
  constexpr uint32_t width = 160, height = 90, frameNumber = 10;
  const auto [reference, waterMask] = referenceWithWater(s, frameNumber, width, height);
  const auto a = supersampledRaster(s, frameNumber, width, height);
  s.render.refraction = "apparent";
  const auto b = supersampledRaster(s, frameNumber, width, height);
  const auto ea = render::tonemappedError(a, reference.rgba, s.render.exposure);
  const auto eb = render::tonemappedError(b, reference.rgba, s.render.exposure);
  const auto wa = render::tonemappedError(a, reference.rgba, s.render.exposure, waterMask);
  const auto wb = render::tonemappedError(b, reference.rgba, s.render.exposure, waterMask);
  std::printf(
      "frame 10, 160x90: accurate RMSE %.4f max %.4f (water %.4f over %zu px); apparent RMSE %.4f max %.4f (water "
      "%.4f)\n",
      ea.rmse, ea.maxError, wa.rmse, wa.pixels, eb.rmse, eb.maxError, wb.rmse);
  ASSERT_GT(wa.pixels, size_t(width * height / 10));
  // The accurate mode within the bound over the frame and on the water, and
  // at least twice as close as the approximation there.
  EXPECT_LT(ea.rmse, kRasterBound);
  EXPECT_LT(wa.rmse, kRasterBound);
  EXPECT_GT(wb.rmse, 2.0 * wa.rmse);
}

// A flat floor (terrain amplitude 0) seen through the water: the cast meets
// it at the top of its zero-thickness slab. The march this cast replaced
// stepped past it in places and showed the walls' colour there: black and
// white specks, each a large error in one pixel.
TEST_F(ReferenceRasterTest, FlatFloorThroughTheWaterMatchesTheReference) {
  // The checker it was measured on: the tiles' grout adds its own error
  // (0.0081 here), which would hide the specks' share.
  scene::Scene s = overThePool(checkerScene());
  s.terrain.amplitude = 0.0f;
  s.render.caustics = false;  // the reference leaves them out
  constexpr uint32_t width = 160, height = 90, frameNumber = 10;
  const auto [reference, waterMask] = referenceWithWater(s, frameNumber, width, height);
  const auto raster = supersampledRaster(s, frameNumber, width, height);
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure, waterMask);
  std::printf("flat floor, frame 10, 160x90: on the water (%zu px) tonemapped RMSE %.4f, max %.4f\n", e.pixels, e.rmse,
              e.maxError);
  ASSERT_GT(e.pixels, size_t(width * height / 10));
  // Measured 0.0040 (0.0056 from the camera before the default scene's
  // art direction); the march it replaced gave 0.0130 there (the specks are a
  // few samples of a pixel's 16).
  EXPECT_LT(e.rmse, 0.008);
}

// The walls' tiles seen through the water at one sample a pixel: filtered
// over the pixel's footprint where the refracted ray meets them (ray
// differentials, as the floor's), they come out as the reference's 64 rays
// average them; point-sampled, their joints broke into dashes.
TEST_F(ReferenceRasterTest, WallsThroughTheWaterAreFilteredAtOneSample) {
  scene::Scene s = scene::defaultScene();
  s.render.caustics = false;  // the reference leaves them out
  s.ao.enabled = false;
  s.spheres.clear();
  s.camera.position = {0.2f, 0.6f, 1.6f};
  s.camera.target = {-0.3f, -0.2f, -0.2f};
  constexpr uint32_t width = 320, height = 180, frameNumber = 10;
  const auto [reference, waterMask] = referenceWithWater(s, frameNumber, width, height);
  render::Renderer renderer(ctx(), s, width, height);
  const auto raster = renderer.render({.frame = frameNumber, .hdr = true}).rgba;
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure, waterMask);
  std::printf("the walls through the water, one sample, 320x180: on the water (%zu px) tonemapped RMSE %.4f\n",
              e.pixels, e.rmse);
  ASSERT_GT(e.pixels, size_t(width * height / 4));
  // Measured 0.0092; point-sampled, 0.0155.
  EXPECT_LT(e.rmse, kRasterBound);
}

// Boxes above the water, through it and piercing it, turned by their yaw:
// drawn, reflected and refracted (castObjects) as the reference's triangles show them.
TEST_F(ReferenceRasterTest, BoxesMatchTheReferenceAboveAndThroughTheWater) {
  scene::Scene s = scene::defaultScene();
  s.render.caustics = false;
  s.camera.position = {2.0f, 1.3f, 2.8f};
  s.camera.target = {-0.2f, -0.5f, -0.4f};
  s.boxes = {{{-0.8f, -0.85f, 0.5f}, {0.7f, 0.5f, 0.5f}, 35.0f, {0.2f, 0.6f, 0.3f}},
             {{0.1f, -0.3f, -1.1f}, {0.9f, 0.7f, 0.35f}, -20.0f, {0.8f, 0.7f, 0.2f}},
             {{-1.3f, 0.25f, -2.4f}, {0.5f, 0.5f, 0.5f}, 0.0f, {0.5f, 0.5f, 0.55f}}};
  constexpr uint32_t width = 160, height = 90, frameNumber = 10;
  const sim::WaterState water = sim::simulateWater(ctx(), s, frameNumber);
  const auto reference = render::renderReference(s, &water, frameNumber, width, height, {.samples = 64});
  const auto raster = supersampledRaster(s, frameNumber, width, height);
  scene::Scene without = s;
  without.boxes.clear();
  const auto noBoxes = render::renderReference(without, &water, frameNumber, width, height, {.samples = 64});
  // The pixels the boxes change, seen directly, reflected or refracted.
  const auto shown = render::tonemapToSrgb8(reference.rgba, s.render.exposure);
  const auto hidden = render::tonemapToSrgb8(noBoxes.rgba, s.render.exposure);
  std::vector<uint8_t> boxPixels(size_t(width) * height, 0);
  for (size_t p = 0; p < boxPixels.size(); ++p) {
    for (int c = 0; c < 3; ++c) boxPixels[p] |= std::abs(int(shown[p * 4 + c]) - int(hidden[p * 4 + c])) > 8;
  }
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure);
  const auto onBoxes = render::tonemappedError(raster, reference.rgba, s.render.exposure, boxPixels);
  std::printf("boxes, frame 10, 160x90: tonemapped RMSE %.4f, max %.4f; on the %zu pixels the boxes change %.4f\n",
              e.rmse, e.maxError, onBoxes.pixels, onBoxes.rmse);
  ASSERT_GT(onBoxes.pixels, size_t(width * height / 40));  // measured 515
  EXPECT_LT(e.rmse, kRasterBound);
  EXPECT_LT(onBoxes.rmse, kRasterBound);
}

// Brick walls seen directly (the raster box-filters the joints over each
// pixel's footprint) and through the water (the water's casts point-sample
// them, as the reference does everywhere): the pattern, its phase and the
// dirt must land where the reference puts them. Thin joints, refracted by the
// waves, need more samples on both sides than the tests above: at the raster's
// 4x4 and the reference's 16, sampling alone put the water's brick pixels at
// 0.0146; at 8x8 and 256 they measured 0.0065, the walls seen directly 0.0039.
TEST_F(ReferenceRasterTest, BrickWallsMatchTheReference) {
  scene::Scene s = scene::defaultScene();
  s.render.caustics = false;
  s.pool.wallPattern = "brick";
  s.pool.brickWidth = 0.3f;
  s.pool.brickHeight = 0.1f;
  s.pool.mortarFraction = 0.18f;
  s.pool.dirt = 0.4f;
  s.camera.position = {1.3f, 0.7f, 1.2f};  // scenes/brick.json: two walls filling the frame, and the water
  s.camera.target = {-2.0f, -0.1f, -0.7f};
  s.camera.fovYDegrees = 60.0f;
  constexpr uint32_t width = 160, height = 90, frameNumber = 10, kSamples = 256;
  const sim::WaterState water = sim::simulateWater(ctx(), s, frameNumber);
  const auto reference = render::renderReference(s, &water, frameNumber, width, height, {.samples = kSamples});
  const auto raster = supersampledRaster(s, frameNumber, width, height, 8);
  scene::Scene plain = s;
  plain.pool.wallPattern = "plain";
  const auto plainReference = render::renderReference(plain, &water, frameNumber, width, height, {.samples = kSamples});
  // The pixels the bricks change, seen directly or through the water.
  const auto shown = render::tonemapToSrgb8(reference.rgba, s.render.exposure);
  const auto hidden = render::tonemapToSrgb8(plainReference.rgba, s.render.exposure);
  std::vector<uint8_t> brickPixels(size_t(width) * height, 0);
  for (size_t p = 0; p < brickPixels.size(); ++p) {
    for (int c = 0; c < 3; ++c) brickPixels[p] |= std::abs(int(shown[p * 4 + c]) - int(hidden[p * 4 + c])) > 8;
  }
  render::Renderer aovRenderer(ctx(), s, width, height, {.aovs = true});
  const std::vector<uint8_t> waterMask =
      render::waterPixelMask(aovRenderer.render({.frame = frameNumber, .hdr = false, .aovs = true}), s.water);
  std::vector<uint8_t> direct(brickPixels.size()), through(brickPixels.size());
  for (size_t p = 0; p < brickPixels.size(); ++p) {
    direct[p] = brickPixels[p] && !waterMask[p];
    through[p] = brickPixels[p] && waterMask[p];
  }
  const auto ed = render::tonemappedError(raster, reference.rgba, s.render.exposure, direct);
  const auto et = render::tonemappedError(raster, reference.rgba, s.render.exposure, through);
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure);
  const auto plainRaster = render::tonemappedError(raster, plainReference.rgba, s.render.exposure, brickPixels);
  std::printf(
      "brick walls, frame 10, 160x90: tonemapped RMSE %.4f, max %.4f; where the bricks show, seen directly "
      "%.4f (%zu px), through the water %.4f (%zu px); the raster against plain walls there %.4f\n",
      e.rmse, e.maxError, ed.rmse, ed.pixels, et.rmse, et.pixels, plainRaster.rmse);
  ASSERT_GT(ed.pixels, size_t(width * height / 40));  // measured 606
  ASSERT_GT(et.pixels, size_t(width * height / 20));  // measured 1368
  EXPECT_LT(e.rmse, kRasterBound);
  EXPECT_LT(ed.rmse, kRasterBound);
  EXPECT_LT(et.rmse, kBricksThroughWaterBound);
  // Plain walls are far from it: the mask holds the pattern, not noise.
  EXPECT_GT(plainRaster.rmse, 10.0 * kRasterBound);
}

TEST(CameraMedium, UnderTheSurfaceInsideThePoolOnly) {
  scene::Scene s = scene::defaultScene();
  const sim::WaterState flat = sim::flatState(s.water.grid);
  auto under = [&](glm::vec3 camera) {
    s.camera.position = camera;
    s.camera.target = camera + glm::vec3(1.0f, 0.0f, 0.0f);
    return render::cameraMedium(s, &flat).extinction.w > 0.0f;
  };
  EXPECT_TRUE(under({0.3f, s.water.level - 0.01f, -0.2f}));
  EXPECT_FALSE(under({0.3f, s.water.level + 0.01f, -0.2f}));
  EXPECT_FALSE(under({0.5f * s.water.extent + 0.01f, s.water.level - 0.5f, 0.0f}));  // outside the pool's square
  EXPECT_TRUE(under({0.5f * s.water.extent - 0.01f, s.water.level - 0.5f, 0.0f}));   // beyond the last cell centre
  EXPECT_FALSE(render::cameraMedium(s, nullptr).extinction.w > 0.0f);
  // On a slope: the mesh's own triangle decides, not the rest level.
  sim::WaterState tilted = flat;
  for (uint32_t j = 0; j < tilted.n; ++j) {
    for (uint32_t i = 0; i < tilted.n; ++i) tilted.u[size_t(j) * tilted.n + i] = 0.01f * float(i);
  }
  s.camera.position = {0.0f, s.water.level + 0.3f, 0.0f};  // x = 0: cell 64 of 128, u there is 0.635
  s.camera.target = {1.0f, 0.0f, 0.0f};
  EXPECT_TRUE(render::cameraMedium(s, &tilted).extinction.w > 0.0f);
}

// The camera under the surface: the pool, a box and the sphere seen through
// the water around it, and the surface from below (refraction into the air,
// total internal reflection past the critical angle), in both modes.
TEST_F(ReferenceRasterTest, CameraUnderTheSurfaceMatchesTheReference) {
  scene::Scene s = scene::defaultScene();
  s.render.caustics = false;
  s.camera.position = {-1.4f, -0.75f, 1.5f};
  s.camera.target = {0.9f, -0.2f, -0.7f};
  s.camera.fovYDegrees = 70.0f;
  s.boxes = {{{-0.6f, -0.9f, -1.0f}, {0.6f, 0.6f, 0.6f}, 30.0f, {0.25f, 0.55f, 0.3f}}};
  constexpr uint32_t width = 160, height = 90, frameNumber = 10;
  const sim::WaterState water = sim::simulateWater(ctx(), s, frameNumber);
  ASSERT_GT(render::cameraMedium(s, &water).extinction.w, 0.0f);
  const auto reference = render::renderReference(s, &water, frameNumber, width, height, {.samples = 64});
  for (const char* mode : {"accurate", "apparent"}) {
    s.render.refraction = mode;
    const auto raster = supersampledRaster(s, frameNumber, width, height);
    const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure);
    std::printf("under water, %s, frame 10, 160x90: tonemapped RMSE %.4f, max %.4f\n", mode, e.rmse, e.maxError);
    EXPECT_LT(e.rmse, kRasterBound) << mode;
  }
}

}  // namespace tp::test
