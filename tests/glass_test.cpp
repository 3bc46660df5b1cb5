// Glass spheres: the optics shared by the raster and the reference
// (shared/glass.h) against Snell's and Fresnel's laws, and the raster's
// image-space refraction (glass.frag, Wyman 2005) against the reference's
// exact two-interface path, and against facts the picture must show. Glass
// boxes: the raster's exact path (glass.frag's box variant) against the
// reference's the same ways (their optics: tests/glass_box_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <utility>

#include "gpu_test.hpp"
#include "reference/glass_view.hpp"
#include "reference/image_error.hpp"
#include "reference/path_tracer.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "shared/glass.h"
#include "shared/objects.h"
#include "sim/water_scene.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

glm::vec3 directionAt(float degreesFromNormal) {
  const float a = glm::radians(degreesFromNormal);
  return {std::sin(a), std::cos(a), 0.0f};  // the normal is +y
}

// One byte a pixel of two linear RGBA frames: 1 where, tonemapped to 8 bits,
// some channel differs by more than 12 of 255.
std::vector<uint8_t> pixelsTheChangeShows(std::span<const float> a, std::span<const float> b, float exposure) {
  const auto ldrA = render::tonemapToSrgb8(a, exposure), ldrB = render::tonemapToSrgb8(b, exposure);
  std::vector<uint8_t> mask(ldrA.size() / 4, 0);
  for (size_t k = 0; k < mask.size(); ++k)
    for (int c = 0; c < 3; ++c) mask[k] = mask[k] || std::abs(int(ldrA[k * 4 + c]) - int(ldrB[k * 4 + c])) > 12;
  return mask;
}

}  // namespace

// Leaving glass of index 1.5 (critical angle asin(1/1.5) = 41.81 degrees):
// below it Snell's law, ior sin(i) = sin(t); past it the internal reflection,
// the tangential part kept and the normal part turned back.
TEST(GlassOptics, ExitRefractsBelowTheCriticalAngleAndReflectsPastIt) {
  const float ior = 1.5f;
  for (float degrees : {0.0f, 10.0f, 30.0f, 41.0f}) {
    const glm::vec3 t = directionAt(degrees), out = shader::glassExitDirection(t, {0.0f, 1.0f, 0.0f}, ior);
    EXPECT_FALSE(shader::glassTotalInternalReflection(t, {0.0f, 1.0f, 0.0f}, ior));
    EXPECT_NEAR(ior * std::sin(glm::radians(degrees)), out.x, 1e-5f) << degrees;
    EXPECT_GT(out.y, 0.0f);
  }
  for (float degrees : {42.0f, 60.0f, 89.0f}) {
    const glm::vec3 t = directionAt(degrees), out = shader::glassExitDirection(t, {0.0f, 1.0f, 0.0f}, ior);
    EXPECT_TRUE(shader::glassTotalInternalReflection(t, {0.0f, 1.0f, 0.0f}, ior)) << degrees;
    EXPECT_NEAR(out.x, t.x, 1e-6f);
    EXPECT_NEAR(out.y, -t.y, 1e-6f);
  }
}

// Fresnel's equations at normal incidence ((n - 1) / (n + 1))^2, 1 at grazing
// incidence and past the critical angle, and the same from either side at
// angles related by Snell's law (Stokes).
TEST(GlassOptics, FresnelReflectance) {
  EXPECT_NEAR(shader::fresnelDielectric(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(shader::fresnelDielectric(1e-4f, 1.0f, 1.5f), 1.0f, 1e-3f);
  EXPECT_EQ(shader::fresnelDielectric(std::cos(glm::radians(45.0f)), 1.5f, 1.0f), 1.0f);
  const float cosI = std::cos(glm::radians(50.0f)), sinT = std::sin(glm::radians(50.0f)) / 1.5f;
  EXPECT_NEAR(shader::fresnelDielectric(cosI, 1.0f, 1.5f),
              shader::fresnelDielectric(std::sqrt(1.0f - sinT * sinT), 1.5f, 1.0f), 1e-6f);
}

// A sphere never traps light: the chord makes the same angle with the normal
// at both ends, so a ray refracted in always leaves (the reference's exact
// exit never meets total internal reflection), over the whole front face.
TEST(GlassOptics, ASphereNeverTotallyReflectsInside) {
  const float ior = 1.5f;
  for (int i = 0; i <= 1000; ++i) {
    const float cosI = std::max(float(i) / 1000.0f, 1e-4f);
    const glm::vec3 n(0.0f, 1.0f, 0.0f), view(std::sqrt(1.0f - cosI * cosI), -cosI, 0.0f);
    const glm::vec3 inside = glm::refract(view, n, 1.0f / ior);
    const glm::vec3 exit = -2.0f * glm::dot(n, inside) * inside + n;  // unit sphere at the origin, entered at n
    EXPECT_FALSE(shader::glassTotalInternalReflection(inside, glm::normalize(exit), ior)) << cosI;
  }
}

// Glass of the water's own index under the water is not there: no
// reflection, and every ray goes straight through along its line. A sphere
// under the water bends the ray by the glass's index over the water's: its
// exit follows Snell's law with that ratio, and the ray leaves at the angle
// to the exit normal it met the front at, as in the air.
TEST(GlassOptics, UnderTheWaterTheGlassBendsByTheRatioOfTheIndices) {
  const float water = 1.333f;
  const shader::GlassSurround pool{0.0f, 10.0f, water};
  const glm::vec3 centre(0.2f, -1.0f, 0.1f);
  const float radius = 0.5f;
  for (int k = 0; k < 200; ++k) {
    // Entry points over the front half seen from straight above.
    const float u = std::fmod(0.618034f * float(k), 1.0f), v = std::fmod(0.754878f * float(k) + 0.1f, 1.0f);
    // Not at grazing, where float round-off alone gives a reflectance of 1e-4.
    const float height = 0.1f + 0.9f * u, phi = 6.2831853f * v, side = std::sqrt(1.0f - height * height);
    const glm::vec3 n(side * std::cos(phi), height, side * std::sin(phi));
    const glm::vec3 p = centre + radius * n, dir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    if (glm::dot(dir, n) >= 0.0f) continue;
    const shader::GlassExit same = shader::glassSphereExactExit(p, dir, n, radius, water, water, pool);
    EXPECT_NEAR(same.reflectance, 0.0f, 1e-7f) << k;
    EXPECT_NEAR(glm::distance(same.leaving, dir), 0.0f, 1e-5f) << k;
    EXPECT_NEAR(glm::length(glm::cross(same.exitPoint - p, dir)), 0.0f, 1e-5f) << k;
    EXPECT_NEAR(glm::distance(same.exitPoint, centre), radius, 1e-5f) << k;

    const float ior = 1.5f;
    const shader::GlassExit g = shader::glassSphereExactExit(p, dir, n, radius, ior, water, pool);
    const float cosI = -glm::dot(dir, n), sinI = std::sqrt(1.0f - cosI * cosI);
    const float sinInside = glm::length(glm::cross(g.inside, n));
    EXPECT_NEAR(ior * sinInside, water * sinI, 1e-5f) << k;
    EXPECT_NEAR(g.reflectance, shader::fresnelDielectric(cosI, water, ior), 1e-6f) << k;
    const glm::vec3 m = glm::normalize(g.exitNormal);
    EXPECT_NEAR(glm::length(glm::cross(g.leaving, m)), sinI, 1e-5f) << k;
    EXPECT_GT(glm::dot(g.leaving, m), 0.0f) << k;
    EXPECT_EQ(g.entryIor, ior / water);
    EXPECT_EQ(g.exitIor, ior / water);
  }
}

// What the raster's search assumes: a ray refracted into a sphere seen from
// outside leaves it through a back face, one the camera does not see, so
// the back faces' depth alone brackets the exit. Over the whole visible cap,
// cameras 1.2 to 20 radii away, indices 1.01 to 3.
TEST(GlassOptics, ASphereIsLeftThroughItsBackFaces) {
  for (float distance : {1.2f, 1.5f, 2.0f, 5.0f, 20.0f}) {
    for (float ior : {1.01f, 1.5f, 3.0f}) {
      const glm::vec3 camera(0.0f, 0.0f, distance);
      size_t rays = 0;
      for (int i = 0; i <= 100; ++i) {
        for (int j = 0; j <= 100; ++j) {
          const glm::vec3 view =
              glm::normalize(glm::vec3(-1.0f + 0.02f * float(i), -1.0f + 0.02f * float(j), -distance));
          const float s = shader::raySphere(camera, view, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
          if (s <= 0.0f) continue;
          const glm::vec3 entry = camera + s * view, inside = glm::refract(view, entry, 1.0f / ior);
          const glm::vec3 exit = entry - 2.0f * glm::dot(entry, inside) * inside;  // its own outward normal
          EXPECT_GT(glm::dot(exit - camera, exit), 0.0f) << distance << " " << ior;
          ++rays;
        }
      }
      EXPECT_GT(rays, 5000u);
    }
  }
}

class GlassTest : public GpuTest {
 protected:
  static scene::Scene withoutGlass(scene::Scene s) {
    std::erase_if(s.spheres, [](const scene::Sphere& sphere) { return scene::isGlass(sphere); });
    std::erase_if(s.boxes, [](const scene::Box& box) { return scene::isGlass(box); });
    return s;
  }

  // The glass of index 1.0001 in `s`, seen against what lies behind it:
  // the frame without it over the glass's pixels, but for those near its
  // rim or its faces' edges, where Fresnel's reflection takes over at
  // grazing incidence whatever the index.
  render::ImageError throughGlassOfIndexNearOne(const scene::Scene& s, uint32_t width, uint32_t height) {
    const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 1});
    auto mask = render::glassPixelMask(reference, s);
    for (size_t k = 0; k < mask.size(); ++k) {
      const glm::vec3 p(reference.position[k * 4], reference.position[k * 4 + 1], reference.position[k * 4 + 2]);
      const glm::vec3 n(reference.normal[k * 4], reference.normal[k * 4 + 1], reference.normal[k * 4 + 2]);
      if (mask[k] && glm::dot(n, glm::normalize(s.camera.position - p)) < 0.3f) mask[k] = 0;
    }
    return againstTheFrameWithoutTheGlass(s, width, height, mask);
  }

  // Seen from above, the channels of the pixels away from the glass box of
  // glassBoxView (and its neighbours) that differ from the frame without it.
  std::pair<size_t, size_t> channelsAwayFromTheBoxThatChange(bool shadows, uint32_t width, uint32_t height) {
    scene::Scene s = render::glassBoxView();
    s.render.shadows = shadows;
    s.camera.position = {0.4f, 3.0f, 2.0f};  // from above: the ground around the box, where its shadow would fall
    const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 1});
    const auto mask = render::glassPixelMask(reference, s);
    render::Renderer withGlass(ctx(), s, width, height);
    const auto glass = withGlass.render({.frame = 0, .hdr = true}).rgba;
    render::Renderer behind(ctx(), withoutGlass(s), width, height);
    const auto plain = behind.render({.frame = 0, .hdr = true}).rgba;
    size_t away = 0, differ = 0;
    for (size_t k = 0; k < mask.size(); ++k) {
      // Its neighbours too: the raster's silhouette is not the reference's to the pixel.
      bool nearGlass = false;
      const int x = int(k % width), y = int(k / width);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int qx = std::clamp(x + dx, 0, int(width) - 1), qy = std::clamp(y + dy, 0, int(height) - 1);
          nearGlass = nearGlass || mask[size_t(qy) * width + size_t(qx)];
        }
      if (nearGlass) continue;
      ++away;
      for (int c = 0; c < 3; ++c) differ += glass[k * 4 + c] != plain[k * 4 + c] ? 1 : 0;
    }
    return std::pair(away, differ);
  }

  // The raster at 4x4 samples per pixel, box filtered, as ReferenceRasterTest
  // compares it (tests/reference_test.cpp).
  std::vector<float> supersampledRaster(const scene::Scene& s, uint32_t width, uint32_t height) {
    constexpr uint32_t factor = 4;
    render::Renderer renderer(ctx(), s, width * factor, height * factor);
    const auto raster = renderer.render({.frame = 0, .hdr = true});
    // The back faces for the spheres' search; a box needs none.
    EXPECT_EQ(render::findPass(raster.passes, render::passes::kGlassBackFaces) != nullptr, scene::hasGlassSpheres(s));
    EXPECT_NE(render::findPass(raster.passes, render::passes::kGlass), nullptr);
    return render::boxDownsample(raster.rgba, width * factor, height * factor, factor);
  }

  // `s`'s glass (its only objects) in the water's rays, at frame 10: on the
  // water's pixels the glass changes in the reference, the raster is nearer
  // the reference with it than half its distance to the reference without it.
  void expectTheWatersRaysMeetTheGlass(const char* name, const scene::Scene& s) {
    constexpr uint32_t width = 160, height = 90, frame = 10;
    const scene::Scene without = withoutGlass(s);
    const sim::WaterState water = sim::simulateWater(ctx(), s, frame);
    const auto reference = render::renderReference(s, &water, frame, width, height, {.samples = 16});
    const auto referenceWithout = render::renderReference(without, &water, frame, width, height, {.samples = 16});
    const auto mask = waterPixelsTheGlassChanges(s, reference, referenceWithout);
    render::Renderer renderer(ctx(), s, width, height);
    const auto raster = renderer.render({.frame = frame}).rgba;
    const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure, mask);
    const auto missing = render::tonemappedError(raster, referenceWithout.rgba, s.render.exposure, mask);
    std::printf(
        "glass %s by the water: %zu water pixels it changes; raster RMSE %.4f against the reference with it, %.4f "
        "without\n",
        name, e.pixels, e.rmse, missing.rmse);
    // Enough pixels for the RMSE to mean something: measured 68 and 30 for
    // the sphere over and under the water (the pool's light by the walls,
    // lit since the walls above the water take their own, moved a few
    // under the cut), 91 and 196 for the box.
    ASSERT_GE(e.pixels, 20u) << name;
    EXPECT_LT(e.rmse, 0.5 * missing.rmse) << name;
  }

  // The water pixels whose reference the glass changes: not the glass's own
  // pixels, and more than 12 of 255 away from the reference without it.
  std::vector<uint8_t> waterPixelsTheGlassChanges(const scene::Scene& s, const render::RenderedFrame& reference,
                                                  const render::RenderedFrame& without) {
    const auto glassPixels = render::glassPixelMask(reference, s);
    auto mask = pixelsTheChangeShows(reference.rgba, without.rgba, s.render.exposure);
    for (size_t k = 0; k < mask.size(); ++k) mask[k] = mask[k] && !glassPixels[k];
    return mask;
  }

  // One sample a pixel against the reference's 64 at 320x180, over the water
  // pixels the glass changes.
  void expectTheWatersRaysThroughGlassFiltered(const char* name, const scene::Scene& s, double bound) {
    constexpr uint32_t width = 320, height = 180, frame = 10;
    const sim::WaterState water = sim::simulateWater(ctx(), s, frame);
    const auto reference = render::renderReference(s, &water, frame, width, height, {.samples = 64});
    const auto without = render::renderReference(withoutGlass(s), &water, frame, width, height, {.samples = 64});
    render::Renderer renderer(ctx(), s, width, height);
    const auto raster = renderer.render({.frame = frame, .hdr = true}).rgba;
    const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure,
                                           waterPixelsTheGlassChanges(s, reference, without));
    std::printf("the floor through water and a glass %s, one sample, 320x180: %zu water pixels, RMSE %.4f\n", name,
                e.pixels, e.rmse);
    // Measured 197 and 380: the sphere's top stands over the water, and
    // what it shows of the water is 1 / n^2 as bright as it was once.
    ASSERT_GT(e.pixels, 150u) << name;
    EXPECT_LT(e.rmse, bound) << name;
  }

  // The frame of `s` against the frame of `s` without its glass, over the
  // pixels of `mask`.
  render::ImageError againstTheFrameWithoutTheGlass(const scene::Scene& s, uint32_t width, uint32_t height,
                                                    std::span<const uint8_t> mask) {
    render::Renderer withGlass(ctx(), s, width, height);
    const auto glass = withGlass.render({.frame = 0, .hdr = true});
    render::Renderer behind(ctx(), withoutGlass(s), width, height);
    const auto background = behind.render({.frame = 0, .hdr = true});
    return render::tonemappedError(glass.rgba, background.rgba, s.render.exposure, mask);
  }
};

// Tonemapped RMSE over the glass pixels, raster against the reference's exact
// exit point at 256 rays a pixel. The glass shows the ground's checker,
// inverted and minified: measured on lavapipe at 160x90 (docs/glass.md)
// 0.0095 with the default 8 search steps, 0.106 with 1 step. The exact
// exit put in the raster's place gives 0.0083 (against 16 rays): the rest
// is the image-space search's own, its exit normal read at a pixel. Since
// the footprints follow the exact paths and filter the sky: 0.0086, and a
// glass box 0.0073 (0.0079 before).
constexpr double kGlassBound = 0.01;
// Glass of index 1.0001 against the frame without it (test below): what is
// left is where the tessellated sphere's silhouette and the ground's
// filtered checker differ from the exact casts'. Measured 0.0083 on
// lavapipe, most of it one pixel at the opaque sphere's silhouette; the
// ground point-sampled in the glass gives 0.0144.
constexpr double kSceneThroughGlassBound = 0.01;
// The floor through glass over still water at one sample a pixel against 64
// rays (test below). Measured on lavapipe 0.0376 with the footprint carried
// through the water, 0.0502 with the rays split there sampled at a point;
// with the footprint halved or doubled, 0.0403 and 0.0389. Since the glass's
// footprints follow its exact paths and filter the sky: 0.0304, and 0.0473
// with the rays split at the water sampled at a point. Since the glass's
// exit under the water refracts into the water: 0.0297.
constexpr double kGlassInWaterAtOneSampleBound = 0.04;
// The floor through the water and then glass under it, at one sample a
// pixel against 64 rays (test below). Measured on lavapipe: a sphere 0.0234
// with the footprint carried through the glass, 0.0444 with the backdrop
// sampled at a point; a box 0.0189, and 0.0389 at a point. (With the glass
// bending as if in the air, its index over the air's, and the backdrop's
// floor flat at its mean depth: 0.0355 and 0.0331. The index over the
// water's with that flat floor: 0.0833 and 0.0767, the floor's relief
// missed where the weaker lens shows the floor under the glass.)
constexpr double kSphereUnderWaterAtOneSampleBound = 0.03;
constexpr double kBoxUnderWaterAtOneSampleBound = 0.025;
// The sky through a glass sphere at one sample a pixel against 64 rays
// (test below). Measured on lavapipe 0.0310 at the footprint's mip level,
// 0.0361 at level 0, 0.0330 and 0.0327 with the footprint doubled and
// halved.
constexpr double kSkyThroughGlassAtOneSampleBound = 0.032;

TEST_F(GlassTest, GlassSphereMatchesTheReferenceWithinTheBound) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = render::glassSphereView();
  const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 256});
  const auto mask = render::glassPixelMask(reference, s);
  const auto raster = supersampledRaster(s, width, height);
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure, mask);
  const auto frame = render::tonemappedError(raster, reference.rgba, s.render.exposure);
  s.render.glassSearchSteps = 1;
  const auto coarse =
      render::tonemappedError(supersampledRaster(s, width, height), reference.rgba, s.render.exposure, mask);
  std::printf("glass sphere, 160x90: %zu glass pixels, RMSE %.4f max %.4f (8 steps), %.4f (1 step); frame RMSE %.4f\n",
              e.pixels, e.rmse, e.maxError, coarse.rmse, frame.rmse);
  ASSERT_GT(e.pixels, size_t(width * height / 20));
  EXPECT_LT(e.rmse, kGlassBound);
  // The search is what finds the exit: one step is several times further off.
  EXPECT_GT(coarse.rmse, 2.0 * e.rmse);
}

// Glass of index barely over 1 bends nothing and reflects nothing: a sphere
// of it against the sky shows the sky behind it, as the frame without it does.
TEST_F(GlassTest, IndexNearOneShowsTheSkyStraightThrough) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = render::glassSphereView();
  // A smooth sky: behind a bend of 1e-4 the clouds' edges would move a texel.
  s.sky.clouds.coverage = 0.0f;
  s.sky.hazeDistance = 0.0f;  // the glass's pixels would be hazed as a surface 3 m off
  s.spheres[0].ior = 1.0001f;
  s.spheres[0].center = {0.0f, 3.0f, -1.0f};  // seen against the sky alone
  s.camera.target = s.spheres[0].center;
  const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 1});
  const auto e = againstTheFrameWithoutTheGlass(s, width, height, render::glassPixelMask(reference, s));
  std::printf("ior 1.0001: %zu glass pixels against the sky behind them: RMSE %.5f, max %.5f\n", e.pixels, e.rmse,
              e.maxError);
  ASSERT_GT(e.pixels, size_t(width * height / 40));  // measured 680
  // The sky texture looked up along nearly the same directions (the
  // reflection of 2.6e-9 of the sky): what is left is the bend of 1e-4.
  EXPECT_LT(e.maxError, 2e-3);
}

// The same glass in front of the ground and an opaque sphere shows them as
// the frame without it does: the rays that leave the glass look up the scene
// (the ground's checker, the sphere and its shadow), not the sky alone.
TEST_F(GlassTest, IndexNearOneShowsTheSceneStraightThrough) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = render::glassSphereView();
  s.spheres[0].ior = 1.0001f;
  s.spheres.push_back({.center = {-0.3f, 0.35f, -1.4f}, .radius = 0.35f, .albedo = {0.8f, 0.3f, 0.2f}});
  s.camera.position = {0.4f, 2.2f, 2.6f};
  s.camera.target = {0.0f, 0.4f, -0.4f};  // the glass seen against the ground and the sphere
  const auto e = throughGlassOfIndexNearOne(s, width, height);
  std::printf("ior 1.0001: %zu glass pixels against the scene behind them: RMSE %.5f, max %.5f\n", e.pixels, e.rmse,
              e.maxError);
  ASSERT_GT(e.pixels, size_t(width * height / 20));  // measured 1166
  EXPECT_LT(e.rmse, kSceneThroughGlassBound);
}

// A ball lens turns the world upside down: seen level with its centre, the
// rays through its upper half leave it going down (the sky's lower half,
// dark), those through its lower half going up (the bright sky).
TEST_F(GlassTest, ABallLensShowsTheSkyUpsideDown) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = render::glassSphereView();
  s.sky.sunRadiance = glm::vec3(0.0f);  // no sun glint to confuse the halves
  s.sky.ground = glm::vec3(0.02f);
  s.ground.albedoA = s.ground.albedoB = glm::vec3(0.02f);  // the world below dark too
  s.camera.position = {0.0f, s.spheres[0].center.y, 3.0f};
  s.camera.target = s.spheres[0].center + glm::vec3(0.0f, 0.0f, -1.0f);
  render::Renderer renderer(ctx(), s, width, height);
  const auto frame = renderer.render({.frame = 0, .hdr = true});
  const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 1});
  const auto mask = render::glassPixelMask(reference, s);
  double upper = 0.0, lower = 0.0;
  size_t upperCount = 0, lowerCount = 0;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t k = size_t(y) * width + x;
      // Away from the rim, where the reflection takes over, and from the middle row.
      const float dx = float(x) + 0.5f - 0.5f * width, dy = float(y) + 0.5f - 0.5f * height;
      if (!mask[k] || std::abs(dy) < 4.0f || dx * dx + dy * dy > 0.4f * 0.4f * height * height) continue;
      const double luminance = frame.rgba[k * 4] + frame.rgba[k * 4 + 1] + frame.rgba[k * 4 + 2];
      (dy < 0.0f ? upper : lower) += luminance;
      ++(dy < 0.0f ? upperCount : lowerCount);
    }
  }
  ASSERT_GT(upperCount, 50u);
  ASSERT_GT(lowerCount, 50u);
  upper /= double(upperCount);
  lower /= double(lowerCount);
  std::printf("ball lens: mean luminance of the upper half %.4f, lower half %.4f\n", upper, lower);
  EXPECT_GT(lower, 5.0 * upper);
}

// Glass is drawn only when glass is in view, its back faces only when a
// glass sphere is; a scene without glass declares nothing of it.
TEST_F(GlassTest, GlassPassesOnlyWhenGlassIsInView) {
  for (scene::Scene s : {render::glassSphereView(), render::glassBoxView()}) {
    s.camera.target = s.camera.position + glm::vec3(0.0f, 0.0f, 1.0f);  // looking away
    render::Renderer away(ctx(), s, 64, 36);
    const auto frame = away.render({.frame = 0, .hdr = true});
    EXPECT_EQ(render::findPass(frame.passes, render::passes::kGlass), nullptr);
    EXPECT_EQ(render::findPass(frame.passes, render::passes::kGlassBackFaces), nullptr);
  }
  render::Renderer none(ctx(), scene::defaultScene(), 64, 36);
  const auto plain = none.render({.frame = 0, .hdr = true});
  EXPECT_EQ(render::findPass(plain.passes, render::passes::kGlass), nullptr);
  // A glass box in view needs no back faces.
  render::Renderer box(ctx(), render::glassBoxView(), 64, 36);
  const auto boxFrame = box.render({.frame = 0, .hdr = true});
  EXPECT_NE(render::findPass(boxFrame.passes, render::passes::kGlass), nullptr);
  EXPECT_EQ(render::findPass(boxFrame.passes, render::passes::kGlassBackFaces), nullptr);
}

// Tonemapped RMSE over the glass box's pixels, the raster against the
// reference at 256 rays a pixel. Both follow the exact path through the box;
// what differs is what the rays that leave meet (the raster's analytic casts,
// the ground's checker filtered over their footprint) and the box's edges.
// Measured 0.0079 on lavapipe at 160x90 (docs/glass.md); the spheres' bound.
constexpr double kGlassBoxBound = kGlassBound;

TEST_F(GlassTest, GlassBoxMatchesTheReferenceWithinTheBound) {
  constexpr uint32_t width = 160, height = 90;
  const scene::Scene s = render::glassBoxView();
  const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 256});
  const auto mask = render::glassPixelMask(reference, s);
  const auto raster = supersampledRaster(s, width, height);
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure, mask);
  std::printf("glass box, 160x90: %zu glass pixels, RMSE %.4f max %.4f\n", e.pixels, e.rmse, e.maxError);
  ASSERT_GT(e.pixels, size_t(width * height / 20));  // measured 937
  EXPECT_LT(e.rmse, kGlassBoxBound);
}

// A glass box of index barely over 1 in front of the ground and an opaque
// sphere shows them as the frame without it does, as a sphere of it does.
TEST_F(GlassTest, GlassBoxOfIndexNearOneShowsTheSceneStraightThrough) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = render::glassBoxView();
  s.boxes[0].ior = 1.0001f;
  s.spheres = {{.center = {-0.3f, 0.35f, -1.4f}, .radius = 0.35f, .albedo = {0.8f, 0.3f, 0.2f}}};
  s.camera.position = {0.4f, 2.2f, 2.6f};
  s.camera.target = {0.0f, 0.4f, -0.4f};  // the glass seen against the ground and the sphere
  const auto e = throughGlassOfIndexNearOne(s, width, height);
  std::printf("glass box of ior 1.0001: %zu pixels against the scene behind them: RMSE %.5f, max %.5f\n", e.pixels,
              e.rmse, e.maxError);
  ASSERT_GT(e.pixels, size_t(width * height / 20));  // measured 801
  EXPECT_LT(e.rmse, kSceneThroughGlassBound);
}

// A glass box casts its shadow and its light (GlassShadowTest measures them
// against the truth) only as render.shadows has it: with them off, away
// from its own pixels the frame with the box is the frame without it, to
// the bit; with them on, the ground round it changes.
TEST_F(GlassTest, AGlassBoxCastsItsLightOnlyWithShadowsOn) {
  constexpr uint32_t width = 160, height = 90;
  for (bool shadows : {false, true}) {
    const auto [away, differ] = channelsAwayFromTheBoxThatChange(shadows, width, height);
    std::printf(
        "glass box from above, shadows %s: %zu pixels away from it, %zu channels differ from the frame "
        "without it\n",
        shadows ? "on" : "off", away, differ);
    ASSERT_GT(away, size_t(width * height / 2));  // measured 13350
    if (shadows) {
      EXPECT_GT(differ, 300u);
    } else {
      EXPECT_EQ(differ, 0u);
    }
  }
}

// The pool's floor seen through glass and then down through the water, at
// one sample a pixel: the pixel's footprint carried on through the flat
// water (the ray differentials refracted at its plane), the tiles' joints
// come out as the reference's 64 rays a pixel average them; sampled at a
// point, as the rays split at the water were, they broke into specks. Over
// the glass above the water: below it the water's own rays see the glass
// (the test after this one).
TEST_F(GlassTest, TheFloorThroughGlassAndWaterIsFilteredAtOneSample) {
  constexpr uint32_t width = 320, height = 180, frame = 10;
  scene::Scene s = scene::defaultScene();
  s.ao.enabled = false;
  s.render.caustics = false;  // a texel's caustic through a lens is a speck of its own
  s.water.drops.clear();      // still water: as flat as the glass's rays take it
  s.spheres = {{.center = {0.6f, 0.05f, 0.6f}, .radius = 0.35f, .material = "glass", .ior = 1.5f}};
  s.camera.position = {1.5f, 0.9f, 2.3f};
  s.camera.target = {0.5f, -0.2f, 0.4f};
  const sim::WaterState water = sim::simulateWater(ctx(), s, frame);
  const auto reference = render::renderReference(s, &water, frame, width, height, {.samples = 64});
  auto mask = render::glassPixelMask(reference, s);
  for (size_t k = 0; k < mask.size(); ++k) mask[k] = mask[k] && reference.position[k * 4 + 1] > s.water.level + 0.05f;
  render::Renderer renderer(ctx(), s, width, height);
  const auto raster = renderer.render({.frame = frame, .hdr = true}).rgba;
  const auto e = render::tonemappedError(raster, reference.rgba, s.render.exposure, mask);
  std::printf("the floor through glass and water, one sample, 320x180: %zu glass pixels, RMSE %.4f\n", e.pixels,
              e.rmse);
  ASSERT_GT(e.pixels, 1500u);
  EXPECT_LT(e.rmse, kGlassInWaterAtOneSampleBound);
}

// Under the water it is the water's rays that meet the glass, and follow its
// paths through the backdrop: with their ray differentials carried through
// the glass (a sphere's curved faces, a box's flat ones and its reflections
// inside) and on through the flat water, the tiles come out as the
// reference's 64 rays a pixel average them; sampled at a point, as they
// were, they broke into specks. Over the water pixels the glass changes in
// the reference (those it does not: the same as without it).
TEST_F(GlassTest, TheFloorThroughWaterAndGlassIsFilteredAtOneSample) {
  scene::Scene s = scene::defaultScene();
  s.ao.enabled = false;
  s.render.caustics = false;
  s.water.drops.clear();
  s.camera.position = {1.3f, 1.2f, 1.9f};
  s.camera.target = {0.5f, -0.4f, 0.5f};
  scene::Scene sphere = s, box = s;
  sphere.spheres = {{.center = {0.6f, -0.25f, 0.6f}, .radius = 0.38f, .material = "glass", .ior = 1.5f}};
  box.spheres.clear();
  box.boxes = {{.center = {0.6f, -0.35f, 0.6f},
                .size = {0.6f, 0.4f, 0.5f},
                .yawDegrees = 30.0f,
                .material = "glass",
                .ior = 1.5f}};
  expectTheWatersRaysThroughGlassFiltered("sphere", sphere, kSphereUnderWaterAtOneSampleBound);
  expectTheWatersRaysThroughGlassFiltered("box", box, kBoxUnderWaterAtOneSampleBound);
}

// Glass of the water's own index under the water bends nothing and reflects
// nothing: seen down through the surface (the water's rays meet it) or from
// a camera under the water (the glass pass draws it), the frame is the frame
// without it, in the reference and the raster alike. Over the pixels where
// glass of index 1.5 in its place shows (the raster's, more than 12 of 255
// from the frame without it).
TEST_F(GlassTest, GlassOfTheWatersIndexUnderTheWaterIsNotSeen) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = scene::defaultScene();
  s.ao.enabled = false;
  s.render.caustics = false;
  s.water.drops.clear();
  s.terrain.amplitude = 0.0f;  // a flat floor, clear of the sphere
  // Clear water: glass of its index is then water in all but name (in
  // absorbing water the glass's chord would be the clearer).
  s.water.absorption = glm::vec3(0.0f);
  s.spheres = {{.center = {0.5f, -0.6f, 0.5f}, .radius = 0.35f, .material = "glass", .ior = 1.5f}};
  scene::Scene above = s, below = s;
  above.camera.position = {1.3f, 1.2f, 1.9f};
  above.camera.target = {0.5f, -0.6f, 0.5f};
  // The surface's mirror from below in view: the water's rays see the glass
  // there, and the walls through it (lib/scene_rays.glsl's backdrop).
  below.camera.position = {-0.9f, -0.5f, 1.4f};
  below.camera.target = {0.5f, -0.6f, 0.5f};
  for (const auto& [name, view] : {std::pair{"from above", above}, std::pair{"from under the water", below}}) {
    const scene::Scene without = withoutGlass(view);
    render::Renderer plainRenderer(ctx(), without, width, height), lensRenderer(ctx(), view, width, height);
    const auto plain = plainRenderer.render({.frame = 0, .hdr = true}).rgba;
    const auto mask =
        pixelsTheChangeShows(lensRenderer.render({.frame = 0, .hdr = true}).rgba, plain, s.render.exposure);
    scene::Scene clear = view;
    clear.spheres[0].ior = view.water.ior;
    render::Renderer clearRenderer(ctx(), clear, width, height);
    const auto raster =
        render::tonemappedError(clearRenderer.render({.frame = 0, .hdr = true}).rgba, plain, s.render.exposure, mask);
    const sim::WaterState water = sim::simulateWater(ctx(), view, 0);
    const auto reference = render::tonemappedError(
        render::renderReference(clear, &water, 0, width, height, {.samples = 4}).rgba,
        render::renderReference(without, &water, 0, width, height, {.samples = 4}).rgba, s.render.exposure, mask);
    std::printf(
        "glass of the water's index under the water, %s: %zu pixels where glass of 1.5 shows; against the frame "
        "without it: raster RMSE %.5f max %.4f, reference RMSE %.5f max %.4f\n",
        name, raster.pixels, raster.rmse, raster.maxError, reference.rmse, reference.maxError);
    ASSERT_GT(raster.pixels, 200u) << name;  // measured 282 and 1115
    // Measured 0 and 0.0014 (the silhouette's pixels). With the glass's
    // index taken over the air's, as it was: 0.062 and 0.140 (the reference
    // 0.070 and 0.089 in a view without the mirror). With the backdrop
    // unshadowed, as it was: 0 and 0.060.
    EXPECT_LT(raster.rmse, 0.01) << name;
    EXPECT_LT(reference.rmse, 1e-4) << name;
  }
}

// Glass standing through the water's surface: radiance over n^2 is kept
// along a ray, so the water's light seen from the air through the glass is
// 1 / n^2 of it, as through the water's own surface. A glass box of index
// 1.5 through still water, seen from the air, against the path-traced truth
// (reference/path_tracer, 256 paths a pixel), over the pixels whose first
// surface is the box above the water: the mean per channel, raster over
// truth, and the tonemapped RMSE there. Measured 1.005, 1.002 and 1.002,
// RMSE 0.0231 (1.002, 0.984 and 0.978, RMSE 0.0238, before the pool's bake
// saw the walls above the water); with the glass's light taken across
// unscaled, as it was,
// 1.086, 1.229 and 1.267, RMSE 0.0664.
TEST_F(GlassTest, GlassThroughTheSurfaceMatchesTheTruth) {
  constexpr uint32_t width = 160, height = 90;
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  s.spheres.clear();
  s.boxes = {{.center = {0.0f, s.water.level + 0.05f, 0.0f},
              .size = {0.7f, 0.5f, 0.45f},
              .yawDegrees = 30.0f,
              .material = "glass",
              .ior = 1.5f}};
  // The sky alone: glass boxes still let the sun through (docs/glass.md).
  s.sky.sunRadiance = glm::vec3(0.0f);
  s.camera.position = {1.1f, 0.8f, 1.5f};
  s.camera.target = {0.0f, -0.2f, 0.0f};
  const sim::WaterState water = sim::simulateWater(ctx(), s, 0);
  const auto truth = render::renderPathTraced(s, &water, 0, width, height, {.samples = 256}).frame;
  auto mask = render::glassPixelMask(truth, s);
  for (size_t k = 0; k < mask.size(); ++k) mask[k] = mask[k] && truth.position[k * 4 + 1] > s.water.level + 0.02f;
  const auto raster = supersampledRaster(s, width, height);
  const std::array<double, 3> ratio = render::meanRatio(raster, truth.rgba, mask);
  const auto e = render::tonemappedError(raster, truth.rgba, s.render.exposure, mask);
  std::printf("glass through the surface: %zu pixels; raster over truth %.3f %.3f %.3f; RMSE %.4f\n", e.pixels,
              ratio[0], ratio[1], ratio[2], e.rmse);
  ASSERT_GT(e.pixels, 400u);  // measured 612
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.1) << "channel " << c;
  EXPECT_LT(e.rmse, 0.035);
}

// A ball lens turns the sky upside down and spreads each pixel's rays over
// many of its texels: the clouds, looked up at level 0, broke into jagged
// specks at one sample a pixel. Looked up at the mip level of each ray's
// footprint they come out as the reference's 64 rays a pixel average them.
TEST_F(GlassTest, TheSkyThroughGlassIsFilteredAtOneSample) {
  constexpr uint32_t width = 320, height = 180;
  const scene::Scene s = render::glassSphereView();
  const auto reference = render::renderReference(s, nullptr, 0, width, height, {.samples = 64});
  render::Renderer renderer(ctx(), s, width, height);
  const auto raster = renderer.render({.frame = 0, .hdr = true}).rgba;
  const auto e =
      render::tonemappedError(raster, reference.rgba, s.render.exposure, render::glassPixelMask(reference, s));
  std::printf("the sky through glass, one sample, 320x180: %zu glass pixels, RMSE %.4f\n", e.pixels, e.rmse);
  ASSERT_GT(e.pixels, 5000u);
  EXPECT_LT(e.rmse, kSkyThroughGlassAtOneSampleBound);
}

// With nothing skipped (every sphere and box drawn, in view or not) the
// glass comes out the same to the bit.
TEST_F(GlassTest, SkippingChangesNoBitOfTheGlass) {
  scene::Scene s = render::glassSphereView();
  s.boxes = render::glassBoxView().boxes;
  s.boxes[0].center = {1.2f, 0.5f, -0.6f};  // beside the sphere
  render::Renderer skipping(ctx(), s, 64, 36), everything(ctx(), s, 64, 36, {.skipping = false});
  EXPECT_EQ(skipping.render({.frame = 0, .hdr = true}).rgba, everything.render({.frame = 0, .hdr = true}).rgba);
}

// Glass in the water's rays: over the water, in its reflection; under it, in
// its refraction. On the water's pixels that the glass changes in the
// reference, the raster is much nearer to the reference with the glass than
// to the reference without it (the same water): the water's casts meet the
// glass.
TEST_F(GlassTest, GlassShowsInTheWatersReflectionsAndRefractions) {
  scene::Scene base = checkerScene();
  base.ao.enabled = false;
  base.render.caustics = false;
  base.spheres.at(0).material = "glass";
  base.spheres.at(0).radius = 0.4f;
  scene::Scene over = base, under = base;
  // Low over the water, where it reflects most.
  over.spheres.at(0).center = {0.0f, base.water.level + 0.45f, -0.6f};
  over.camera.position = {0.3f, 0.2f, 3.2f};
  over.camera.target = {0.0f, -0.1f, 0.0f};
  under.spheres.at(0).center = {0.0f, base.water.level - 0.55f, 0.3f};
  under.camera.position = {0.4f, 1.1f, 3.9f};
  under.camera.target = {0.0f, -0.4f, 0.2f};
  expectTheWatersRaysMeetTheGlass("sphere reflected", over);
  expectTheWatersRaysMeetTheGlass("sphere refracted", under);
}

// The same for a glass box, turned, in the sphere's places. Over the water
// a wide, low one: the rays the water reflects up into its sides reflect
// off its top inside and leave going down; a box shows what lies behind it
// moved and mirrored, and a tall one over the water shows the sky as the
// water without it does.
TEST_F(GlassTest, GlassBoxShowsInTheWatersReflectionsAndRefractions) {
  scene::Scene base = checkerScene();
  base.ao.enabled = false;
  base.render.caustics = false;
  base.spheres.clear();
  scene::Scene over = base, under = base;
  over.boxes = {{.center = {0.0f, base.water.level + 0.3f, -0.6f},
                 .size = {1.4f, 0.3f, 1.2f},
                 .yawDegrees = 25.0f,
                 .material = "glass",
                 .ior = 1.5f}};
  over.camera.position = {0.3f, 0.3f, 3.2f};
  over.camera.target = {0.0f, -0.1f, 0.0f};
  under.boxes = {{.center = {0.0f, base.water.level - 0.55f, 0.3f},
                  .size = {0.8f, 0.5f, 0.7f},
                  .yawDegrees = 25.0f,
                  .material = "glass",
                  .ior = 1.5f}};
  under.camera.position = {0.4f, 1.1f, 3.9f};
  under.camera.target = {0.0f, -0.4f, 0.2f};
  expectTheWatersRaysMeetTheGlass("box reflected", over);
  expectTheWatersRaysMeetTheGlass("box refracted", under);
}

}  // namespace tp::test
