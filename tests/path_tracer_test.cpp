// The path tracer (reference/path_tracer), the ground truth, against answers
// worked out here independently of it: a plane's irradiance under the sky by
// quadrature, white furnaces (every surface white, lossless water and glass,
// a uniform sky: every path sees the sky's radiance, times n^2 inside the
// water), the floor of a clear pool lit by the sun through flat water, and
// a wall above it lit by the sun and the sun's image in the water.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "exact_fresnel.hpp"
#include "reference/environment_light.hpp"
#include "reference/path_bsdf.hpp"
#include "reference/path_tracer.hpp"
#include "shading/sky_model.hpp"
#include "sim/water_state.hpp"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

// The mean of a frame's channel c over its pixels.
double meanChannel(const render::RenderedFrame& f, int c) {
  double sum = 0.0;
  for (size_t k = 0; k < size_t(f.width) * f.height; ++k) sum += f.rgba[k * 4 + c];
  return sum / double(size_t(f.width) * f.height);
}

// Every surface white, the sky 1 in every direction, no sun, water and glass lossless.
scene::Scene whiteFurnace() {
  scene::Scene s = checkerScene();
  s.sky.zenith = s.sky.horizon = s.sky.ground = glm::vec3(1.0f);
  s.sky.glow = glm::vec3(0.0f);
  s.sky.sunRadiance = glm::vec3(0.0f);
  s.ground.albedoA = s.ground.albedoB = glm::vec3(1.0f);
  s.pool.wallAlbedo = s.pool.tileAlbedoA = s.pool.tileAlbedoB = glm::vec3(1.0f);
  s.water.absorption = s.water.scattering = glm::vec3(0.0f);
  s.water.drops.clear();
  s.spheres.clear();
  scene::Sphere glass;
  glass.material = "glass";
  glass.center = {0.6f, s.water.level, 0.3f};  // half under the water
  glass.radius = 0.4f;
  scene::Sphere white;
  white.center = {-0.7f, s.water.level - 0.3f, -0.4f};
  white.radius = 0.35f;
  white.albedo = glm::vec3(1.0f);
  s.spheres = {glass, white};
  s.camera.position = {2.5f, 2.2f, 3.0f};
  s.camera.target = {0.0f, s.water.level - 0.3f, 0.0f};
  return s;
}

}  // namespace

TEST(PathTracer, GroundIsLitByTheSkysAndTheSunsExactIrradiance) {
  scene::Scene s = checkerScene();
  s.water.enabled = false;
  s.spheres.clear();
  s.boxes.clear();
  s.ground.albedoA = s.ground.albedoB = glm::vec3(0.5f);
  s.camera.position = {0.0f, 2.0f, 1.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fovYDegrees = 30.0f;
  // The sky's irradiance on an upward plane by the midpoint rule in
  // (cos theta, phi), and the sun's as its radiance times the disc's solid
  // angle times the cosine of its centre (exact to 1e-4 for a degree's disc).
  const shader::SkyParams sky = render::skyParams(s.sky);
  constexpr int kRings = 2000, kSegments = 512;
  glm::dvec3 irradiance(0.0);
  for (int i = 0; i < kRings; ++i) {
    const double mu = (i + 0.5) / kRings;
    for (int j = 0; j < kSegments; ++j) {
      const double phi = glm::two_pi<double>() * (j + 0.5) / kSegments, r = std::sqrt(1.0 - mu * mu);
      const glm::vec3 d(float(r * std::cos(phi)), float(mu), float(r * std::sin(phi)));
      irradiance += glm::dvec3(shader::skyRadiance(sky, d, 0.0f)) * mu * (glm::two_pi<double>() / kRings / kSegments);
    }
  }
  irradiance += glm::dvec3(render::sunIrradiance(s.sky)) * std::sin(glm::radians(double(s.sky.sunElevationDegrees)));
  const render::PathTracedFrame traced = render::renderPathTraced(s, nullptr, 0, 8, 8, {.samples = 256});
  for (int c = 0; c < 3; ++c) {
    const double expected = 0.5 / glm::pi<double>() * irradiance[c];
    std::printf("channel %d: traced %.5f, exact %.5f\n", c, meanChannel(traced.frame, c), expected);
    EXPECT_NEAR(meanChannel(traced.frame, c) / expected, 1.0, 0.005) << "channel " << c;
  }
}

TEST(PathTracer, WhiteFurnaceSeenFromTheAirIsTheSkysRadiance) {
  const scene::Scene s = whiteFurnace();
  const sim::WaterState water = sim::flatState(s.water.grid);
  const render::PathTracedFrame traced = render::renderPathTraced(s, &water, 0, 24, 16, {.samples = 64});
  const double mean = meanChannel(traced.frame, 1);
  std::printf("white furnace from the air: mean %.4f (exact 1)\n", mean);
  EXPECT_NEAR(mean, 1.0, 0.01);
}

TEST(PathTracer, WhiteFurnaceSeenFromUnderTheWaterIsNSquaredTheSky) {
  scene::Scene s = whiteFurnace();
  s.camera.position = {1.2f, s.water.level - 0.4f, 1.5f};
  s.camera.target = {0.0f, s.water.level - 0.2f, 0.0f};
  const sim::WaterState water = sim::flatState(s.water.grid);
  // 512 paths a pixel: at 64 the image's mean was 1.6% off by noise alone
  // (the light trapped under the surface takes many bounces out).
  const render::PathTracedFrame traced = render::renderPathTraced(s, &water, 0, 24, 16, {.samples = 512});
  const double mean = meanChannel(traced.frame, 1), exact = double(s.water.ior) * s.water.ior;
  std::printf("white furnace under the water: mean %.4f (exact n^2 = %.4f)\n", mean, exact);
  EXPECT_NEAR(mean / exact, 1.0, 0.01);
}

TEST(PathTracer, PoolFloorIsLitByTheSunThroughFlatWater) {
  // Only the sun; a flat floor of albedo rho in a pool of black walls under
  // flat absorbing water; the camera looks down at the floor's middle. The
  // floor's irradiance is the sun's horizontal flux times Fresnel's
  // transmission at the sun's angle, absorbed over the slant path down; its
  // radiance, Lambert's; the camera sees it through the surface, absorbed
  // over the slant path up, times the transmission at the view's angle over
  // n^2. The floor's light reflected back down by the surface and lit again
  // adds at most rho / (1 - rho): the bound above.
  scene::Scene s = checkerScene();
  s.sky.zenith = s.sky.horizon = s.sky.ground = s.sky.glow = glm::vec3(0.0f);
  s.sky.sunElevationDegrees = 60.0f;
  const float rho = 0.02f;
  s.pool.tileAlbedoA = s.pool.tileAlbedoB = glm::vec3(rho);
  s.pool.wallAlbedo = s.ground.albedoA = s.ground.albedoB = glm::vec3(0.0f);
  s.terrain.amplitude = 0.0f;
  s.water.absorption = {0.1f, 0.3f, 0.6f};
  s.water.drops.clear();
  s.spheres.clear();
  s.boxes.clear();
  s.camera.position = {0.0f, s.water.level + 2.0f, 0.4f};
  s.camera.target = {0.0f, s.ground.height - s.pool.depth, 0.0f};
  s.camera.fovYDegrees = 8.0f;
  const sim::WaterState water = sim::flatState(s.water.grid);
  const uint32_t w = 4, h = 4;
  const render::PathTracedFrame traced = render::renderPathTraced(s, &water, 0, w, h, {.samples = 256});
  const double n = s.water.ior, depth = s.water.level - (s.ground.height - s.pool.depth);
  const double sinSun = std::sin(glm::radians(double(s.sky.sunElevationDegrees)));
  const double cosSunInWater = std::sqrt(1.0 - (1.0 - sinSun * sinSun) / (n * n));
  const glm::dvec3 sunFlux = glm::dvec3(render::sunIrradiance(s.sky)) * sinSun * (1.0 - fresnelFromAir(sinSun, n));
  // Each camera path is reflected (black) or refracted at the surface by
  // Fresnel's odds: a pixel's 256 paths leave it 1% of noise (one standard
  // deviation), the 16 pixels' mean a quarter of that. The mean is held to
  // 1%, each pixel to five of its deviations.
  const double upper = 1.0 + rho / (1.0 - rho);
  glm::dvec3 meanRatio(0.0);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const size_t k = size_t(y) * w + x;
      // The view ray through the pixel's centre reaches the floor here; the
      // pixel's rays spread over a hundredth of a degree more.
      const glm::dvec3 floorPoint(traced.frame.position[k * 4], traced.frame.position[k * 4 + 1],
                                  traced.frame.position[k * 4 + 2]);
      const glm::dvec3 toEye = glm::normalize(glm::dvec3(s.camera.position) - floorPoint);
      const double cosView = toEye.y;  // the ray's angle in the air: the surface is flat
      const double cosViewInWater = std::sqrt(1.0 - (1.0 - cosView * cosView) / (n * n));
      for (int c = 0; c < 3; ++c) {
        const double sigma = s.water.absorption[c];
        const double floorRadiance = rho / glm::pi<double>() * sunFlux[c] * std::exp(-sigma * depth / cosSunInWater);
        const double seen =
            floorRadiance * std::exp(-sigma * depth / cosViewInWater) * (1.0 - fresnelFromAir(cosView, n)) / (n * n);
        const double ratio = traced.frame.rgba[k * 4 + c] / seen;
        meanRatio[c] += ratio / double(w * h);
        EXPECT_GT(ratio, 0.95) << "pixel " << x << "," << y << " channel " << c;
        EXPECT_LT(ratio, 1.05 * upper) << "pixel " << x << "," << y << " channel " << c;
      }
    }
  }
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: traced over exact, the pixels' mean %.4f (at most %.4f)\n", c, meanRatio[c], upper);
    EXPECT_GT(meanRatio[c], 0.99) << "channel " << c;
    EXPECT_LT(meanRatio[c], 1.01 * upper) << "channel " << c;
  }
}

TEST(PathTracer, GgxLobeSamplingMatchesItsDensity) {
  // The density sampleBsdf reports, integrated over the hemisphere (midpoint
  // rule), and the share of its draws the lobe sends under the surface
  // (lost), add up to 1; its weights average to the BSDF's albedo integral.
  const render::SurfaceBsdf m{glm::vec3(0.6f), 0.5f, 0.4f};
  const glm::vec3 n(0.0f, 1.0f, 0.0f), wo = glm::normalize(glm::vec3(0.5f, 0.8f, 0.1f));
  constexpr int kRings = 1000, kSegments = 400;
  double pdfIntegral = 0.0, reflected = 0.0;
  for (int i = 0; i < kRings; ++i) {
    const double mu = (i + 0.5) / kRings;
    for (int j = 0; j < kSegments; ++j) {
      const double phi = glm::two_pi<double>() * (j + 0.5) / kSegments, r = std::sqrt(1.0 - mu * mu);
      const glm::vec3 wi(float(r * std::cos(phi)), float(mu), float(r * std::sin(phi)));
      const double dOmega = glm::two_pi<double>() / kRings / kSegments;
      pdfIntegral += render::bsdfPdf(m, n, wo, wi) * dOmega;
      reflected += render::bsdfTimesCosine(m, n, wo, wi).x * dOmega;
    }
  }
  double sampled = 0.0, lost = 0.0;
  constexpr int kSamples = 200000;
  for (int k = 0; k < kSamples; ++k) {
    const glm::vec3 u((k + 0.5f) / kSamples, std::fmod(k * 0.6180339887f, 1.0f), std::fmod(k * 0.7548776662f, 1.0f));
    const render::BsdfSample b = render::sampleBsdf(m, n, wo, u);
    sampled += b.weight.x;
    if (b.pdf <= 0.0f) lost += 1.0;
  }
  EXPECT_NEAR(pdfIntegral + lost / kSamples, 1.0, 2e-3);
  EXPECT_NEAR(sampled / kSamples, reflected, 5e-3 * reflected);
}

TEST(PathTracer, WallAboveFlatWaterIsLitByTheSunAndItsMirrorImage) {
  // Only the sun, low enough for the water to mirror a seventh of it; a
  // wall of albedo rho above flat clear water, facing the sun (azimuth 0:
  // the sun towards +x, the wall at x = -extent/2 facing +x), ground, floor
  // and the other walls black. The wall's irradiance is the sun's through
  // its cosine, direct and mirrored by the water (the mirror image's cosine
  // on a vertical wall is the same), the mirrored times Fresnel's
  // reflectance at the sun's angle; the near rim shades neither: the sun
  // grazing it falls below the water at the far wall, and the mirror points
  // lie out of its shadow on the water. The wall's light reflected by the
  // water and lit again adds at most rho / (1 - rho). The sun's disc is 4
  // degrees wide, so that the wall's own directions meet its mirror image
  // often: counted by both estimators unweighted, the mirror image read
  // 1.14; without its light sample (a 1-degree disc), 0.88.
  scene::Scene s = checkerScene();
  s.sky.zenith = s.sky.horizon = s.sky.ground = s.sky.glow = glm::vec3(0.0f);
  s.sky.sunElevationDegrees = 20.0f;
  s.sky.sunAzimuthDegrees = 0.0f;
  s.sky.sunAngularRadiusDegrees = 4.0f;
  const float rho = 0.02f;
  s.pool.wallAlbedo = glm::vec3(rho);
  s.pool.tileAlbedoA = s.pool.tileAlbedoB = s.ground.albedoA = s.ground.albedoB = glm::vec3(0.0f);
  s.pool.wallSpecular = 0.0f;
  s.terrain.amplitude = 0.0f;
  s.water.level = -0.6f;
  s.water.absorption = s.water.scattering = glm::vec3(0.0f);
  s.water.drops.clear();
  s.spheres.clear();
  s.boxes.clear();
  const float wallX = -0.5f * s.water.extent, middle = s.water.level + 0.3f;
  s.camera.position = {wallX + 3.5f, s.ground.height + 0.3f, 0.0f};
  s.camera.target = {wallX, middle, 0.0f};
  s.camera.fovYDegrees = 4.0f;
  const sim::WaterState water = sim::flatState(s.water.grid);
  const render::PathTracedFrame traced = render::renderPathTraced(s, &water, 0, 4, 4, {.samples = 256});
  const double sinSun = std::sin(glm::radians(double(s.sky.sunElevationDegrees)));
  const double cosOnWall = std::cos(glm::radians(double(s.sky.sunElevationDegrees)));
  const double mirrored = fresnelFromAir(sinSun, s.water.ior);
  const double upper = 1.0 + rho / (1.0 - rho);
  for (int c = 0; c < 3; ++c) {
    const double exact =
        rho / glm::pi<double>() * double(render::sunIrradiance(s.sky)[c]) * cosOnWall * (1.0 + mirrored);
    const double ratio = meanChannel(traced.frame, c) / exact;
    std::printf("channel %d: traced over exact %.4f (the mirror image's share %.4f)\n", c, ratio,
                mirrored / (1.0 + mirrored));
    EXPECT_GT(ratio, 0.99) << "channel " << c;
    EXPECT_LT(ratio, 1.01 * upper) << "channel " << c;
  }
}

}  // namespace tp::test
