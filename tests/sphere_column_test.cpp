// The sphere's volume per water column (shared/sphere_column.h) against
// independent answers: the spherical cap's closed-form volume (the columns of
// a grid must add up to it) and, column by column, a fine double-precision
// midpoint rule over the square; and its smoothness as the sphere moves,
// where a centre sample jumps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "shared/sphere_column.h"
#include "sim/wake_measures.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

// The sphere's vertical chord below the level at one point, in double.
double chordAt(double x, double z, glm::dvec3 c, double radius, double level) {
  const double r2 = radius * radius - (x - c.x) * (x - c.x) - (z - c.z) * (z - c.z);
  if (r2 <= 0.0) return 0.0;
  const double s = std::sqrt(r2);
  return std::max(0.0, std::min(c.y + s, level) - (c.y - s));
}

// Midpoint rule with m x m points over the square [lo, lo + h]^2.
double midpointVolume(glm::dvec2 lo, double h, glm::dvec3 c, double radius, double level, int m) {
  double sum = 0.0;
  for (int b = 0; b < m; ++b) {
    for (int a = 0; a < m; ++a) sum += chordAt(lo.x + (a + 0.5) * h / m, lo.y + (b + 0.5) * h / m, c, radius, level);
  }
  return sum * (h / m) * (h / m);
}

double gridVolume(uint32_t n, double extent, glm::vec3 c, float radius, float level) {
  return sumOverCells(n, float(extent),
                      [&](glm::vec2 lo, glm::vec2 hi) { return shader::sphereColumnVolume(lo, hi, c, radius, level); });
}

}  // namespace

// Over a whole grid the columns hold the cap below the level, whatever the
// sphere's depth (above, half, deep, fully under), size against the cell, and
// offset against the grid. Measured worst relative error: 3.0e-6 (float); one
// Gauss rule over the rows, not split at the kinks, was off by 2.3e-3.
TEST(SphereColumn, ColumnsAddUpToTheSphericalCap) {
  double worst = 0.0;
  for (const uint32_t n : {32u, 128u, 512u}) {
    for (const float radius : {0.05f, 0.25f, 0.45f}) {
      for (const float depth : {-0.8f, -0.3f, 0.0f, 0.3f, 0.8f, 1.2f}) {  // of the centre below the level, in radii
        const glm::vec3 c(2.0137f, 1.0f - depth * radius, 1.9731f);
        const double exact = sim::sphereCapVolume(radius, c.y, 1.0);
        const double got = gridVolume(n, 4.0, c, radius, 1.0f);
        const double error = std::abs(got - exact) / exact;
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-5) << "n " << n << ", radius " << radius << ", depth " << depth;
      }
    }
  }
  std::printf("worst relative error of a grid's columns against the cap: %.2e\n", worst);
}

// Column by column, against a 400 x 400 midpoint rule in double, over the
// columns the rim and the level's circle cross (where the integrand has its
// kinks): worst error relative to h^2 r (a column's volume is up to 2 h^2 r).
// Measured: 4.7e-6 (the unsplit rule: 4.3e-4).
TEST(SphereColumn, EachColumnMatchesAFineQuadrature) {
  const double h = 4.0 / 128.0;
  const glm::dvec3 c(1.0 + 0.37 * h, 0.9, 1.0 + 0.61 * h);
  const double radius = 0.25, level = 1.0;
  double worst = 0.0;
  for (int j = 20; j < 44; ++j) {
    for (int i = 20; i < 44; ++i) {
      const glm::dvec2 lo(i * h, j * h);
      const double expected = midpointVolume(lo, h, c, radius, level, 400);
      const double got =
          shader::sphereColumnVolume(glm::vec2(lo), glm::vec2(lo + h), glm::vec3(c), float(radius), float(level));
      worst = std::max(worst, std::abs(got - expected) / (h * h * radius));
    }
  }
  std::printf("worst column error against the midpoint rule: %.2e of h^2 r\n", worst);
  EXPECT_LT(worst, 2e-5);
}

// Moving across the grid in small steps, a column's volume changes by a
// bounded amount per step (it is continuous with a bounded derivative), where
// the centre sample's chord leaps as the rim crosses the centre: the largest
// change per step, over the column's area, against the step.
TEST(SphereColumn, ChangesSmoothlyAsTheSphereMoves) {
  const double h = 4.0 / 128.0, radius = 0.45, level = 0.0, step = h / 64.0;
  const glm::dvec2 lo(2.0, 2.0);
  double worstArea = 0.0, worstCentre = 0.0;
  double lastArea = 0.0, lastCentre = 0.0;
  for (int k = 0; k <= 64 * 40; ++k) {
    const glm::dvec3 c(2.0 - radius - 2.0 * h + k * step, level, 2.0 + 0.3 * h);
    const double area =
        shader::sphereColumnVolume(glm::vec2(lo), glm::vec2(lo + h), glm::vec3(c), float(radius), float(level)) /
        (h * h);
    const double centre = chordAt(lo.x + 0.5 * h, lo.y + 0.5 * h, c, radius, level);
    if (k > 0) {
      worstArea = std::max(worstArea, std::abs(area - lastArea) / step);
      worstCentre = std::max(worstCentre, std::abs(centre - lastCentre) / step);
    }
    lastArea = area;
    lastCentre = centre;
  }
  std::printf("steepest change per metre moved: area %.2f, centre sample %.2f\n", worstArea, worstCentre);
  // The area's rate is bounded by the chord's mean over the cell's leading
  // edge, sqrt(2 r h) / h at the rim; the centre sample's grows without bound
  // as the step shrinks (sqrt(2 r / step)).
  EXPECT_LT(worstArea, 1.2 * std::sqrt(2.0 * radius * h) / h);
  EXPECT_GT(worstCentre, 2.0 * worstArea);
}

}  // namespace tp::test
