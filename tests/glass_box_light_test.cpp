// The glass boxes' light grids (shading/glass_box_light) against closed
// forms: a wide thin slab lets the sun through by Fresnel's equations at
// its two faces and its reflections between them, and glass of index one
// lets all of it through.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "shading/glass_box_light.hpp"
#include "shading/sky_model.hpp"
#include "shared/sun_shadow.h"

namespace tp::test {
namespace {

// Unpolarised reflectance at a face between indices n1 and n2, from
// Fresnel's equations, written out here.
double reflectance(double cosI, double n1, double n2) {
  const double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
  if (sinT >= 1.0) return 1.0;
  const double cosT = std::sqrt(1.0 - sinT * sinT);
  const double s = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  const double p = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return 0.5 * (s * s + p * p);
}

scene::Scene slabScene(float ior) {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;
  s.spheres.clear();
  s.sky.sunElevationDegrees = 50.0f;
  s.boxes = {{.center = {0.0f, 0.6f, 0.0f},
              .size = {3.0f, 0.05f, 3.0f},
              .yawDegrees = 20.0f,
              .material = "glass",
              .ior = ior}};
  return s;
}

// The grid's value at a point under the slab's middle, on the ground.
float valueUnderTheMiddle(const render::GlassBoxGrid& g, const scene::Scene& s, float height) {
  const glm::vec3 toSun = render::sunDirection(s.sky);
  const glm::vec2 a = shader::sunSheared(glm::vec3(0.0f, height, 0.0f), toSun, toSun, false, 0.0f, g.heights.z);
  const float side = float(TP_GLASS_BOX_SIDE - 1);
  const int u = int(std::lround((a.x - g.square.x) / (g.square.z - g.square.x) * side));
  const int v = int(std::lround((a.y - g.square.y) / (g.square.w - g.square.y) * side));
  const int l = int(std::lround((height - g.heights.x) / (g.heights.y - g.heights.x) * (TP_GLASS_BOX_LAYERS - 1)));
  return g.values[(size_t(l) * TP_GLASS_BOX_SIDE + size_t(v)) * TP_GLASS_BOX_SIDE + size_t(u)];
}

}  // namespace

// Light through a slab leaves parallel to itself: under its middle the sun
// is what the two faces let through, (1 - R)^2 (1 + R^2 + R^4 + ...) =
// (1 - R) / (1 + R), less the reflections the grid drops (R^2 of R^2).
TEST(GlassBoxLight, ASlabLetsTheSunThroughByFresnel) {
  const scene::Scene s = slabScene(1.5f);
  const render::GlassBoxGrid g = render::glassBoxLightGrid(s, s.boxes[0]);
  const double cosI = render::sunDirection(s.sky).y;
  const double r = reflectance(cosI, 1.0, 1.5);
  const double expected = (1.0 - r) / (1.0 + r);
  for (int l = 0; l < TP_GLASS_BOX_LAYERS; l += 4) {
    std::printf("layer %d:", l);
    for (int u = 0; u < TP_GLASS_BOX_SIDE; u += 6)
      std::printf(" %.3f", g.values[(size_t(l) * TP_GLASS_BOX_SIDE + 48) * TP_GLASS_BOX_SIDE + u]);
    std::printf("\n");
  }
  for (float height : {0.0f, 0.2f, 0.4f}) {
    const float value = valueUnderTheMiddle(g, s, height);
    std::printf("slab of index 1.5, %.1f m high: %.4f, Fresnel's %.4f\n", height, value, expected);
    EXPECT_NEAR(value, expected, 0.005) << height;
  }
}

// Glass of index one loses no light: each layer's light, the grid's mean
// over it, is the open sun's. It may move it: a ray that meets a face near
// grazing is turned by far more than the index's step, as Snell's law has
// it, and the light on either side of the edge's shadow moves by a few per
// cent. Away from those lines the grid is 1.
TEST(GlassBoxLight, GlassOfIndexOneLosesNoLight) {
  scene::Scene s = slabScene(1.0001f);
  s.boxes[0].size = {0.7f, 0.5f, 0.45f};
  const render::GlassBoxGrid g = render::glassBoxLightGrid(s, s.boxes[0]);
  constexpr size_t layer = size_t(TP_GLASS_BOX_SIDE) * TP_GLASS_BOX_SIDE;
  size_t off = 0;
  float worst = 0.0f;
  for (size_t l = 0; l < TP_GLASS_BOX_LAYERS; ++l) {
    double sum = 0.0;
    for (size_t k = l * layer; k < (l + 1) * layer; ++k) {
      sum += g.values[k];
      if (std::abs(g.values[k] - 1.0f) > 0.01f) ++off;
      worst = std::max(worst, std::abs(g.values[k] - 1.0f));
    }
    EXPECT_NEAR(sum / layer, 1.0, 0.001) << "layer " << l;
  }
  std::printf("glass of index 1.0001: %zu of %zu points more than 1%% off the open sun, the worst %.4f\n", off,
              g.values.size(), worst);
  // Measured 2467 points (1.1%), the worst 0.053 off; with the box's light
  // not let through (its Fresnel share taken as 1), the layers' means drop.
  EXPECT_LT(off, g.values.size() / 50);
  EXPECT_LT(worst, 0.1f);
}

}  // namespace tp::test
