// The pool's baked light (shading/pool_light.hpp) against closed forms: a
// floor under flat water in a pool so wide that its walls are out of sight,
// under a uniform sky. Black surfaces: the sky through Snell's window with
// Fresnel's transmission and the absorption down, integrated over the air's
// directions by quadrature (the bake draws the water's). Surfaces of albedo
// rho and clear water: that light times 1 / (1 - rho R), R the underside's
// reflectance of the floor's Lambertian light (total internal reflection
// outside the window), each bounce's light sent back by the surface. A
// black sky and a sun: the floor's sunlit glow sent back the same way. The
// walls above the water: the sky over the rim, the sky and the sun the flat
// water mirrors (Fresnel's reflectance), and the floor's light through the
// surface (Fresnel's transmission, 1 / n^2 of its radiance).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "scene/scene.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_light.hpp"
#include "shading/pool_model.hpp"
#include "shared/glass.h"
#include "shared/pool_light.h"

namespace tp::test {
namespace {

// A pool 100 m wide, 1.05 m of water over a flat floor, every surface of
// albedo `rho`, the water absorbing `absorption` per metre.
scene::Scene widePool(float rho, float absorption) {
  scene::Scene s;
  s.water.extent = 100.0f;
  s.water.absorption = glm::vec3(absorption);
  s.water.scattering = glm::vec3(0.0f);
  s.terrain.amplitude = 0.0f;
  s.pool.floorPattern = "checker";
  s.pool.tileAlbedoA = s.pool.tileAlbedoB = glm::vec3(rho);
  s.pool.wallPattern = "plain";
  s.pool.wallAlbedo = glm::vec3(rho);
  return s;
}

// The baked irradiance over the floor's middle 8 x 8 texels (25 m and more
// from the walls), averaged: each texel's bounced light is a Monte Carlo
// estimate (measured: about 1% from texel to texel with bounces, none
// without), their mean within about 0.15%.
// Under a sky of radiance `sky` and `sun`.
float middleOfTheFloor(const scene::Scene& s, float sky = 1.0f, render::PoolLightSun sun = {}) {
  const render::PoolModel model = render::poolModel(s);
  const std::vector<glm::vec4> all =
      render::bakePoolLight(
          model.params, model.floorVertices, [&](glm::vec3) { return glm::vec3(sky); }, sun, render::opaqueBoxes(s))
          .floorAndLight;
  const glm::vec4* light = all.data() + model.floorVertices.size();
  constexpr int kFrom = TP_POOL_LIGHT_FLOOR / 4, kTo = 3 * TP_POOL_LIGHT_FLOOR / 4;
  double sum = 0.0;
  for (int j = kFrom; j < kTo; ++j)
    for (int i = kFrom; i < kTo; ++i) sum += light[j * TP_POOL_LIGHT_FLOOR + i].y;
  return float(sum / double((kTo - kFrom) * (kTo - kFrom)));
}

// The irradiance under `depth` of water absorbing `absorption` from a sky
// of radiance 1: 2 pi times the integral over the air's cosines of the
// transmission, the cosine and the absorption along the refracted slant.
double skyThroughTheWindow(double ior, double depth, double absorption) {
  const int steps = 200000;
  double sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double mu = (k + 0.5) / steps;
    const double cosWater = std::sqrt(1.0 - (1.0 - mu * mu) / (ior * ior));
    const double t = 1.0 - shader::fresnelDielectric(float(mu), 1.0f, float(ior));
    sum += t * mu * std::exp(-absorption * depth / cosWater);
  }
  return 2.0 * glm::pi<double>() * sum / steps;
}

// The share of a Lambertian surface's light the water's underside sends
// back: 2 times the integral of Fresnel's reflectance times the cosine.
double undersideReflectance(double ior) {
  const int steps = 200000;
  double sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double mu = (k + 0.5) / steps;
    sum += shader::fresnelDielectric(float(mu), float(ior), 1.0f) * mu;
  }
  return 2.0 * sum / steps;
}

// The baked irradiance of the walls above the water, averaged over the
// middle half of wall `wall` (poolLightWall's order; -1: all four), every
// row of the dry band.
double middleOfTheDryBand(const scene::Scene& s, float sky, render::PoolLightSun sun = {}, int wall = -1) {
  const render::PoolModel model = render::poolModel(s);
  const std::vector<glm::vec4> all =
      render::bakePoolLight(
          model.params, model.floorVertices, [&](glm::vec3) { return glm::vec3(sky); }, sun, render::opaqueBoxes(s))
          .floorAndLight;
  const glm::vec4* dry = all.data() + model.floorVertices.size() + TP_POOL_LIGHT_DRY_START;
  double sum = 0.0;
  int count = 0;
  for (int w = 0; w < 4; ++w) {
    if (wall >= 0 && w != wall) continue;
    for (int row = 0; row < TP_POOL_LIGHT_UP; ++row)
      for (int i = TP_POOL_LIGHT_ALONG / 4; i < 3 * TP_POOL_LIGHT_ALONG / 4; ++i, ++count)
        sum += dry[(w * TP_POOL_LIGHT_UP + row) * TP_POOL_LIGHT_ALONG + i].y;
  }
  return sum / count;
}

// The integral over a vertical wall's half of the lower hemisphere of
// `f`(mu) times the cosine to the wall's normal, mu the cosine from the
// nadir: 2 times the integral of f(mu) sqrt(1 - mu^2) over mu.
template <typename F>
double lowerQuarter(const F& f) {
  const int steps = 200000;
  double sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double mu = (k + 0.5) / steps;
    sum += f(mu) * std::sqrt(1.0 - mu * mu);
  }
  return 2.0 * sum / steps;
}

}  // namespace

// A wall above black water under a sky of radiance 1, the far walls 100 m
// off: the sky over the rim, half the upper hemisphere (pi / 2), and the
// sky the water mirrors, Fresnel's reflectance times the cosine over the
// lower quarter. The open sky's SH9, the raster's light there before, took
// the ground's light for the lower quarter.
TEST(PoolLight, AWallAboveTheWaterSeesTheSkyAndTheWatersMirror) {
  const scene::Scene s = widePool(0.0f, 0.0f);
  const double ior = s.water.ior;
  const double expected = glm::pi<double>() / 2.0 + lowerQuarter([&](double mu) {
                            return double(shader::fresnelDielectric(float(mu), 1.0f, float(ior)));
                          });
  const double baked = middleOfTheDryBand(s, 1.0f);
  std::printf("the sky on the dry band: baked %.5f, closed form %.5f, ratio %.5f\n", baked, expected, baked / expected);
  EXPECT_NEAR(baked / expected, 1.0, 0.005);
}

// The same walls under a lid laid on the rim, a uniform sky and a sun:
// the lid's underside, which neither lights, hides the sky over the rim,
// the sky and the sun the water mirrors, and the sun on the other walls.
// The walls above the water are dark.
TEST(PoolLight, ALidOnTheRimLeavesTheWallsAboveTheWaterDark) {
  scene::Scene s = widePool(0.0f, 0.0f);
  s.pool.wallAlbedo = glm::vec3(0.5f);
  const render::PoolLightSun sun{glm::normalize(glm::vec3(0.6f, 0.5f, 0.2f)), glm::vec3(3.0f)};
  const double open = middleOfTheDryBand(s, 1.0f, sun);
  scene::Box lid;
  lid.size = glm::vec3(2000.0f, 0.2f, 2000.0f);
  lid.center = glm::vec3(0.0f, s.ground.height + 0.101f, 0.0f);
  s.boxes.push_back(lid);
  const double covered = middleOfTheDryBand(s, 1.0f, sun);
  std::printf("the dry band: %.5f open, %.3g under the lid\n", open, covered);
  EXPECT_GT(open, 1.0);
  EXPECT_EQ(covered, 0.0);
}

// The sun mirrored by flat water onto the wall at -x (inward normal +x):
// Fresnel's reflectance at the sun's elevation times the cosine of the
// mirrored sun to the wall. The sun's own arrival is not the bake's.
TEST(PoolLight, AWallAboveTheWaterTakesTheSunTheWaterMirrors) {
  const scene::Scene s = widePool(0.0f, 0.0f);
  const glm::vec3 toSun = glm::normalize(glm::vec3(0.6f, 0.5f, 0.2f));
  const double expected = shader::fresnelDielectric(toSun.y, 1.0f, s.water.ior) * toSun.x;
  const double baked = middleOfTheDryBand(s, 0.0f, {toSun, glm::vec3(1.0f)}, 0);
  std::printf("the mirrored sun on the dry band: baked %.6f, closed form %.6f\n", baked, expected);
  EXPECT_NEAR(baked / expected, 1.0, 1e-3);
  // The walls it does not face take none.
  EXPECT_EQ(middleOfTheDryBand(s, 0.0f, {toSun, glm::vec3(1.0f)}, 1), 0.0);
}

// The pool's light through the surface: under a sun at the zenith and no
// sky, a floor of albedo rho in clear water, the walls black, sends up rho /
// pi times the sun's irradiance through the surface, 1 - F(1), in every
// direction, and more by its bounces off the underside: at most 1 / (1 -
// rho R) times that, as in the pool's middle; less where the floor is near
// the black wall, which the wall's rays reach (a floor and walls both of
// albedo 0.5 under a uniform sky gave 0.905 of the middle's light there).
// Out of the water the light keeps Fresnel's transmission over n^2 of its
// radiance, over the lower quarter. The sun neither lights the wall nor
// meets its mirror there.
TEST(PoolLight, AWallAboveTheWaterSeesThePoolsLightThroughTheSurface) {
  const float rho = 0.2f;
  scene::Scene s = widePool(rho, 0.0f);
  s.pool.wallAlbedo = glm::vec3(0.0f);
  const double ior = s.water.ior;
  const double direct = rho / glm::pi<double>() * (1.0 - shader::fresnelDielectric(1.0f, 1.0f, float(ior)));
  const double out =
      lowerQuarter([&](double mu) { return 1.0 - double(shader::fresnelDielectric(float(mu), 1.0f, float(ior))); }) /
      (ior * ior);
  const double least = direct * out, most = least / (1.0 - rho * undersideReflectance(ior));
  const double baked = middleOfTheDryBand(s, 0.0f, {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f)});
  std::printf("the pool's light on the dry band: baked %.5f, closed forms without and with the bounces %.5f %.5f\n",
              baked, least, most);
  // The bounces' Monte Carlo noise, about 1% of them (measured on the floor).
  EXPECT_GT(baked, least * 0.995);
  EXPECT_LT(baked, most * 1.005);
}

TEST(PoolLight, TheSkyThroughFlatWaterOnABlackFloorIsTheWindowsIntegral) {
  for (const float absorption : {0.0f, 0.3f, 1.2f}) {
    SCOPED_TRACE(absorption);
    const scene::Scene s = widePool(0.0f, absorption);
    const double depth = s.water.level - (s.ground.height - s.pool.depth);
    const double expected = skyThroughTheWindow(s.water.ior, depth, absorption);
    const double baked = middleOfTheFloor(s);
    std::printf("absorption %.1f: baked %.5f, closed form %.5f, ratio %.5f\n", absorption, baked, expected,
                baked / expected);
    EXPECT_NEAR(baked / expected, 1.0, 0.005);
  }
}

// The floor texel (i, j)'s baked irradiance, among `boxes`.
glm::vec3 floorTexel(const scene::Scene& s, int i, int j, render::PoolLightSun sun = {}) {
  const render::PoolModel model = render::poolModel(s);
  const std::vector<glm::vec4> all =
      render::bakePoolLight(
          model.params, model.floorVertices, [&](glm::vec3) { return glm::vec3(1.0f); }, sun, render::opaqueBoxes(s))
          .floorAndLight;
  return glm::vec3(all[model.floorVertices.size() + size_t(j * TP_POOL_LIGHT_FLOOR + i)]);
}

// A black box in the air over a black floor under a sky of radiance 1:
// the window's integral (as skyThroughTheWindow) over the air's directions
// whose line, refracted up from the texel's point and on out of the water,
// misses the box (a slab test here), by quadrature over the cosine and the
// azimuth. Without the box the bake gives the whole window.
TEST(PoolLight, ABoxInTheAirHidesTheSkyItStandsBefore) {
  scene::Scene s = widePool(0.0f, 0.3f);
  const int texel = TP_POOL_LIGHT_FLOOR / 2;
  const float half = 0.5f * s.water.extent;
  const float x = (2.0f * (float(texel) + 0.5f) / TP_POOL_LIGHT_FLOOR - 1.0f) * half;
  const glm::vec3 p(x, s.ground.height - s.pool.depth, x);
  const double depth = s.water.level - p.y, ior = s.water.ior;
  scene::Box box;
  box.size = glm::vec3(1.2f, 0.5f, 0.8f);
  box.center = glm::vec3(x + 0.3f, s.water.level + 1.0f, x - 0.2f);
  box.albedo = glm::vec3(0.0f);
  const glm::vec3 low = box.center - 0.5f * box.size, high = box.center + 0.5f * box.size;
  auto misses = [&](glm::dvec3 o, glm::dvec3 d) {
    double near = 0.0, far = 1e30;
    for (int a = 0; a < 3; ++a) {
      const double t0 = (low[a] - o[a]) / d[a], t1 = (high[a] - o[a]) / d[a];
      near = std::max(near, std::min(t0, t1));
      far = std::min(far, std::max(t0, t1));
    }
    return near > far;
  };
  const int steps = 1500;
  double sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double mu = (k + 0.5) / steps, sinAir = std::sqrt(1.0 - mu * mu);
    const double sinWater = sinAir / ior, cosWater = std::sqrt(1.0 - sinWater * sinWater);
    const double t = 1.0 - shader::fresnelDielectric(float(mu), 1.0f, float(ior));
    for (int m = 0; m < 4 * steps; ++m) {
      const double phi = 2.0 * glm::pi<double>() * (m + 0.5) / (4 * steps);
      const glm::dvec3 across(std::cos(phi), 0.0, std::sin(phi));
      const glm::dvec3 q = glm::dvec3(p) + depth * (across * (sinWater / cosWater) + glm::dvec3(0.0, 1.0, 0.0));
      if (misses(q, across * sinAir + glm::dvec3(0.0, mu, 0.0)))
        sum += t * mu * std::exp(-double(s.water.absorption.x) * depth / cosWater);
    }
  }
  const double expected = sum * 2.0 * glm::pi<double>() / (double(steps) * 4 * steps);
  const double open = floorTexel(s, texel, texel).y;
  s.boxes.push_back(box);
  const double baked = floorTexel(s, texel, texel).y;
  std::printf("under a box in the air: baked %.5f, quadrature %.5f, ratio %.5f; without the box %.5f\n", baked,
              expected, baked / expected, open);
  EXPECT_NEAR(baked / expected, 1.0, 0.01);
  EXPECT_GT(open / expected, 1.1);  // what the box takes is ten times the bound
}

// A lid: a box over the whole pool, just above the water, which stands at
// the rim. Nothing reaches the water but through the lid, whose underside
// neither the sky nor the sun lights: the pool is dark, the sun's bounces
// and the light around included, whatever the lid's albedo.
TEST(PoolLight, ALidOverTheWaterLeavesThePoolDark) {
  scene::Scene s = widePool(0.5f, 0.0f);
  s.water.level = s.ground.height;
  scene::Box lid;
  // 2 km wide, 1 mm over the water: a line out of it at a grazing angle
  // could pass under the lid's edge only below 1e-6 of a radian.
  lid.size = glm::vec3(2000.0f, 0.2f, 2000.0f);
  lid.center = glm::vec3(0.0f, s.water.level + 0.101f, 0.0f);
  lid.albedo = glm::vec3(0.8f);
  const render::PoolLightSun sun{glm::normalize(glm::vec3(0.3f, 0.8f, 0.1f)), glm::vec3(3.0f)};
  const render::PoolModel model = render::poolModel(s);
  const size_t first = model.floorVertices.size();
  auto bake = [&] {
    return render::bakePoolLight(
               model.params, model.floorVertices, [](glm::vec3) { return glm::vec3(1.0f); }, sun,
               render::opaqueBoxes(s))
        .floorAndLight;
  };
  const std::vector<glm::vec4> open = bake();
  s.boxes.push_back(lid);
  const std::vector<glm::vec4> covered = bake();
  double lit = 0.0, dark = 0.0;
  for (size_t k = first; k < covered.size(); ++k) {
    lit += std::abs(open[k].x) + std::abs(open[k].y) + std::abs(open[k].z);
    dark += std::abs(covered[k].x) + std::abs(covered[k].y) + std::abs(covered[k].z);
  }
  std::printf("the pool's light summed: %.3f open, %.3g under the lid\n", lit, dark);
  EXPECT_GT(lit, 1.0);
  EXPECT_EQ(dark, 0.0);
}

TEST(PoolLight, TheUndersideSendsTheFloorsLightBackAsItsReflectanceSays) {
  const double direct = skyThroughTheWindow(scene::Water{}.ior, 1.0, 0.0);
  const double r = undersideReflectance(scene::Water{}.ior);
  for (const float rho : {0.5f, 0.8f}) {
    SCOPED_TRACE(rho);
    const double expected = direct / (1.0 - rho * r);
    const double baked = middleOfTheFloor(widePool(rho, 0.0f));
    std::printf("albedo %.1f: baked %.5f, closed form %.5f (R %.4f), ratio %.5f\n", rho, baked, expected, r,
                baked / expected);
    EXPECT_NEAR(baked / expected, 1.0, 0.005);
  }
}

// The sun's light bounced: the floor lit by the sun through the flat
// surface (Fresnel's transmission times the cosine in the air: the solid
// angle's compression cancels the cosine in the water) sends rho of it up,
// R of that comes back, and so on; the sun's own first arrival is not the
// bake's (the raster draws it with its caustics and shadows).
TEST(PoolLight, TheSunsBouncesAreTheFloorsLightSentBack) {
  const float ior = scene::Water{}.ior;
  const double r = undersideReflectance(ior);
  const glm::vec3 toSun = glm::normalize(glm::vec3(0.4f, 0.8f, 0.2f));
  const double direct = (1.0 - shader::fresnelDielectric(toSun.y, 1.0f, ior)) * toSun.y;
  for (const float rho : {0.5f, 0.8f}) {
    SCOPED_TRACE(rho);
    const double expected = direct * rho * r / (1.0 - rho * r);
    const double baked = middleOfTheFloor(widePool(rho, 0.0f), 0.0f, {toSun, glm::vec3(1.0f)});
    std::printf("albedo %.1f: baked %.5f, closed form %.5f, ratio %.5f\n", rho, baked, expected, baked / expected);
    EXPECT_NEAR(baked / expected, 1.0, 0.01);
  }
}

// The light around at each point of its grid (shared/pool_light.h), black
// surfaces and clear water under a uniform sky of radiance 1: from below,
// the sky fills Snell's window at n^2 times Fresnel's transmission, and
// nothing else is lit (outside the window the underside reflects the black
// floor). Its SH9 coefficients are the zonal integrals 2 pi of that
// radiance times each basis function over the cosine from the zenith, by
// quadrature here; the others vanish.
TEST(PoolLight, TheLightAroundIsSnellsWindowInSh9) {
  const scene::Scene s = widePool(0.0f, 0.0f);
  const render::PoolModel model = render::poolModel(s);
  const render::PoolLight light =
      render::bakePoolLight(model.params, model.floorVertices, [](glm::vec3) { return glm::vec3(1.0f); }, {}, {});
  const double ior = s.water.ior;
  const int steps = 200000;
  double expected[9] = {};
  for (int k = 0; k < steps; ++k) {
    const double mu = (k + 0.5) / steps;  // the cosine from the zenith, in the water
    const double radiance = (1.0 - shader::fresnelDielectric(float(mu), float(ior), 1.0f)) * ior * ior;
    const glm::vec3 d(float(std::sqrt(1.0 - mu * mu)), float(mu), 0.0f);
    for (uint32_t i : {0u, 1u, 6u})
      expected[i] += 2.0 * glm::pi<double>() * radiance * double(shader::sh9Basis(i, d)) / steps;
  }
  // In a pool 100 m wide no point's window reaches a wall.
  const size_t first = model.floorVertices.size() + TP_POOL_LIGHT_TEXELS;
  for (uint32_t k = 0; k < TP_POOL_AROUND_POINTS; ++k) {
    for (uint32_t i = 0; i < 9; ++i) {
      const float baked = light.floorAndLight.at(first + 9 * k + i).y;
      if (k == 0) std::printf("coefficient %u: baked %.5f, quadrature %.5f\n", i, baked, expected[i]);
      EXPECT_NEAR(baked, expected[i], 0.005 * expected[0]) << "point " << k << " coefficient " << i;
    }
  }
  // The lookup between the points gives the same.
  const shader::Sh9 between =
      shader::poolLightAround(model.params, glm::vec3(3.0f, -0.5f, -7.0f), light.floorAndLight.data());
  for (uint32_t i = 0; i < 9; ++i) EXPECT_NEAR(between.c[i].y, expected[i], 0.005 * expected[0]) << i;
}

// The lookup of the light around between its grid's points: a light that
// is a linear function of where it is comes back exactly between the
// points, and is held at the outer ones beyond them.
TEST(PoolLight, TheLightAroundIsTrilinearBetweenItsPoints) {
  const scene::Scene s = widePool(0.0f, 0.0f);
  const render::PoolModel model = render::poolModel(s);
  std::vector<glm::vec4> buffer = model.floorVertices;
  const size_t first = buffer.size() + TP_POOL_LIGHT_TEXELS;
  buffer.resize(buffer.size() + TP_POOL_LIGHT_SIZE, glm::vec4(0.0f));
  auto linear = [](glm::vec3 p, uint32_t i) { return 1.0f + 0.01f * p.x - 0.3f * p.y + 0.02f * p.z + float(i); };
  for (int k = 0; k < TP_POOL_AROUND_POINTS; ++k) {
    const glm::vec3 p = shader::poolAroundPoint(model.params, k);
    for (uint32_t i = 0; i < 9; ++i) buffer[first + 9 * size_t(k) + i] = glm::vec4(linear(p, i));
  }
  const glm::vec3 lowest = shader::poolAroundPoint(model.params, 0);
  const glm::vec3 highest = shader::poolAroundPoint(model.params, TP_POOL_AROUND_POINTS - 1);
  for (const glm::vec3 p : {glm::vec3(3.0f, -0.5f, -7.0f), glm::vec3(-20.0f, -0.9f, 11.0f), lowest, highest}) {
    const shader::Sh9 sh = shader::poolLightAround(model.params, p, buffer.data());
    for (uint32_t i = 0; i < 9; ++i) EXPECT_NEAR(sh.c[i].x, linear(p, i), 1e-4f) << p.x << " " << p.y << " " << i;
  }
  // Past the outer points, in the corner of the pool and at the surface.
  const glm::vec3 corner(-49.0f, s.water.level, 49.0f);
  const glm::vec3 held(lowest.x, lowest.y, highest.z);
  const shader::Sh9 sh = shader::poolLightAround(model.params, corner, buffer.data());
  for (uint32_t i = 0; i < 9; ++i) EXPECT_NEAR(sh.c[i].x, linear(held, i), 1e-4f) << i;
}

}  // namespace tp::test
