// A glass sphere's sun table (shading/glass_caustic) against answers worked
// out here: the ray's passage by the angles of geometric optics (the
// rainbow's construction with no internal reflection), the lens formula for
// a ball's paraxial focus, the light through both faces by Fresnel's
// equations, and the open sun where the ball is not in the way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "exact_fresnel.hpp"
#include "shading/glass_caustic.hpp"
#include "shading/pool_model.hpp"
#include "shared/sun_shadow.h"

namespace tp::test {
namespace {

constexpr double kColumnStep = TP_GLASS_TABLE_REACH / (TP_GLASS_TABLE_COLUMNS - 1);
constexpr double kRowStep = TP_GLASS_TABLE_DEPTH / (TP_GLASS_TABLE_ROWS - 1);

double at(const std::vector<float>& table, int row, int column) {
  return table[size_t(row * TP_GLASS_TABLE_COLUMNS + column)];
}

// Each column's tent integrated against the area's weight rho drho: the
// light a row's column stands for, in units of 2 pi.
double columnWeight(int column) {
  return column == 0 ? kColumnStep * kColumnStep / 6.0 : column * kColumnStep * kColumnStep;
}

// The light a row adds to the open sun's (negative: it takes), over the
// table's disc, in units of the light through one unit of area.
double addedLight(const std::vector<float>& table, int row) {
  double sum = 0.0;
  for (int c = 0; c < TP_GLASS_TABLE_COLUMNS; ++c) sum += (at(table, row, c) - 1.0) * columnWeight(c);
  return 2.0 * glm::pi<double>() * sum;
}

}  // namespace

// A ray at distance b from the axis meets the unit sphere at incidence i =
// asin(b), crosses it at t = asin(b / n) along a chord that turns the point
// by pi - 2t about the centre, and leaves turned by 2(i - t) towards the axis.
TEST(GlassCaustic, PassageMatchesTheAnglesOfGeometricOptics) {
  for (double ior : {1.33, 1.5, 2.0}) {
    for (double b : {0.01, 0.3, 0.6, 0.9, 0.999}) {
      const render::GlassPassage g = render::glassPassage(b, ior);
      const double i = std::asin(b), t = std::asin(b / ior);
      const double exitAngle = i + glm::pi<double>() - 2.0 * t;  // from the sun-facing pole
      const double turn = 2.0 * (i - t);
      EXPECT_NEAR(g.entryAlong, -std::cos(i), 1e-12);
      EXPECT_NEAR(g.exitAcross, std::sin(exitAngle), 1e-12) << "ior " << ior << " b " << b;
      EXPECT_NEAR(g.exitAlong, -std::cos(exitAngle), 1e-12) << "ior " << ior << " b " << b;
      EXPECT_NEAR(g.directionAcross, -std::sin(turn), 1e-12) << "ior " << ior << " b " << b;
      EXPECT_NEAR(g.directionAlong, std::cos(turn), 1e-12) << "ior " << ior << " b " << b;
      const double through = 1.0 - fresnelFromAir(std::cos(i), ior);
      EXPECT_NEAR(g.transmitted, through * through, 1e-6);
    }
  }
}

// A ball lens of index n brings rays near the axis to a focus n / (2 (n - 1))
// radii past its centre.
TEST(GlassCaustic, ParaxialRaysFocusWhereTheLensFormulaSays) {
  for (double ior : {1.33, 1.5, 1.8}) {
    const render::GlassPassage g = render::glassPassage(1e-4, ior);
    const double focus = g.exitAlong - g.exitAcross / g.directionAcross * g.directionAlong;
    EXPECT_NEAR(focus, ior / (2.0 * (ior - 1.0)), 1e-6) << "ior " << ior;
  }
}

// Just behind the ball the light the table adds to the open sun's is the
// ball's disc taken out (-pi) and what both faces let through put back:
// every ray that leaves the ball forwards, its share by Fresnel's equations.
TEST(GlassCaustic, LightJustBehindTheBallIsWhatFresnelLetsThrough) {
  for (double ior : {1.33, 1.5}) {
    double through = 0.0;
    constexpr int kSteps = 200000;
    for (int k = 0; k < kSteps; ++k) {
      const double b = (k + 0.5) / kSteps, i = std::asin(b), t = std::asin(b / ior);
      if (2.0 * (i - t) >= glm::half_pi<double>()) continue;  // it leaves backwards
      const double f = 1.0 - fresnelFromAir(std::cos(i), ior);
      through += f * f * 2.0 * glm::pi<double>() * b / kSteps;
    }
    const std::vector<float> table = render::glassCausticTable(ior, 0.0);
    const int row = int(std::ceil(1.0 / kRowStep));  // the first row past the ball's back
    const double expected = through - glm::pi<double>(), got = addedLight(table, row);
    std::printf("ior %.2f, %.3f radii past the centre: added light %.5f, Fresnel %.5f\n", ior, row * kRowStep, got,
                expected);
    EXPECT_NEAR(got, expected, 0.005 * glm::pi<double>());
  }
}

// Beside the ball the sun is open: on the centre's plane every column past
// the ball reads 1, out to the table's edge, and no row darkens its edge.
TEST(GlassCaustic, OpenSunBesideTheBall) {
  const std::vector<float> table = render::glassCausticTable(1.5, glm::radians(1.0));
  for (int c = int(std::ceil(1.05 / kColumnStep)); c < TP_GLASS_TABLE_COLUMNS; ++c)
    EXPECT_NEAR(at(table, 0, c), 1.0, 1e-3) << "column " << c;
  shader::GlassTables tables{};
  std::copy(table.begin(), table.end(), tables.values);
  for (int r = 0; r < TP_GLASS_TABLE_ROWS; ++r) {
    const float edge = shader::glassTableAt(tables, 0u, 0.985f * float(TP_GLASS_TABLE_REACH), float(r * kRowStep));
    EXPECT_GT(edge, 0.97f) << "row " << r;
  }
}

// The sun's disc spreads the light over a row and keeps it: halfway down the
// table the light added with a sun of 1 degree is that with a point sun.
TEST(GlassCaustic, SunsDiscSpreadsTheLightAndKeepsIt) {
  const std::vector<float> point = render::glassCausticTable(1.5, 0.0);
  const std::vector<float> disc = render::glassCausticTable(1.5, glm::radians(1.0));
  const int row = TP_GLASS_TABLE_ROWS / 2;
  std::printf("added light %.5f with a point sun, %.5f with the disc\n", addedLight(point, row), addedLight(disc, row));
  EXPECT_NEAR(addedLight(disc, row), addedLight(point, row), 0.01 * glm::pi<double>());
  // The disc softens the caustic: its brightest value falls.
  double brightestPoint = 0.0, brightestDisc = 0.0;
  for (int c = 0; c < TP_GLASS_TABLE_COLUMNS; ++c) {
    brightestPoint = std::max(brightestPoint, at(point, row, c));
    brightestDisc = std::max(brightestDisc, at(disc, row, c));
  }
  EXPECT_LT(brightestDisc, brightestPoint);
}

// The shaders' read: a table's values at its points, between them the mix.
TEST(GlassCaustic, ShadersReadTheTableAtItsPoints) {
  shader::GlassTables tables{};
  for (int k = 0; k < TP_GLASS_TABLE_SIZE; ++k) tables.values[TP_GLASS_TABLE_SIZE + k] = float(k);
  const float across = float(5 * kColumnStep), along = float(7 * kRowStep);
  EXPECT_NEAR(shader::glassTableAt(tables, 1u, across, along), 7 * TP_GLASS_TABLE_COLUMNS + 5, 1e-3);
  EXPECT_NEAR(shader::glassTableAt(tables, 1u, across + float(0.5 * kColumnStep), along),
              7 * TP_GLASS_TABLE_COLUMNS + 5.5, 1e-3);
  // Past the last row, the last row.
  EXPECT_NEAR(shader::glassTableAt(tables, 1u, 0.0f, 1000.0f), (TP_GLASS_TABLE_ROWS - 1) * TP_GLASS_TABLE_COLUMNS,
              1e-3);
}

// glassSunShare finds the table of each sphere by its place: behind it along
// the sun the table's row, beside it or before it the open sun.
TEST(GlassCaustic, SunShareReadsTheTableBehindTheSphere) {
  shader::ShadowCasters casters{};
  casters.glass.x = 1.0f;
  casters.glassSpheres[0] = glm::vec4(1.0f, 2.0f, 0.0f, 0.5f);
  shader::GlassTables tables{};
  const std::vector<float> table = render::glassCausticTable(1.5, glm::radians(1.0));
  std::copy(table.begin(), table.end(), tables.values);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const int row = 12;
  const glm::vec3 behind(1.0f, 2.0f - 0.5f * float(row * kRowStep), 0.0f);
  EXPECT_NEAR(shader::glassSunShare(casters, tables, behind, up), at(table, row, 0), 1e-5);
  EXPECT_EQ(shader::glassSunShare(casters, tables, glm::vec3(1.0f, 3.0f, 0.0f), up), 1.0f);  // towards the sun
  EXPECT_EQ(shader::glassSunShare(casters, tables, glm::vec3(2.1f, 0.0f, 0.0f), up), 1.0f);  // beside
}

// Only glass in the air casts: above the water's rest level, or off the pool.
TEST(GlassCaustic, OnlyGlassInTheAirCasts) {
  scene::Scene s = scene::defaultScene();
  s.spheres.clear();
  const float level = s.water.level, half = 0.5f * s.water.extent;
  auto glass = [](glm::vec3 c, float r) {
    scene::Sphere g;
    g.material = "glass";
    g.center = c;
    g.radius = r;
    return g;
  };
  s.spheres = {glass({0.0f, level + 0.31f, 0.0f}, 0.3f),
               glass({0.5f, level, 0.0f}, 0.3f),
               glass({half + 0.31f, level - 0.1f, 0.0f}, 0.3f),
               {.center = {0.0f, 1.0f, 1.0f}, .radius = 0.2f}};
  const auto casters = render::glassCasters(s, 0.0f);
  ASSERT_EQ(casters.size(), 2u);
  EXPECT_EQ(casters[0], &s.spheres[0]);
  EXPECT_EQ(casters[1], &s.spheres[2]);
  s.render.shadows = false;
  EXPECT_TRUE(render::glassCasters(s, 0.0f).empty());
}

}  // namespace tp::test
