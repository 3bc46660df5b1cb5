// The spread forcing's volume per water column (shared/sphere_spread.h)
// against independent answers: the submerged part's moments against a
// midpoint rule over the ball in double precision, the normal tail against
// std::erfc, each column against a midpoint rule over the Gaussian density
// on its square, and a grid's columns against the spherical cap's closed
// form, at a wall and across a wrapped edge.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <utility>

#include "shared/sphere_column.h"
#include "shared/sphere_spread.h"
#include "sim/wake_measures.hpp"
#include "sim/water_params.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

// The widening per metre of depth the tests give the header: any factor
// will do, and this one is the renderer's (sim::kSpreadDepthFactor) rounded.
constexpr float kDepthFactor = 0.65f;

struct DoubleMoments {
  double volume = 0.0, variance = 0.0, meanDepth = 0.0;
};

// The ball of `radius` about the origin, below the level `above` over its
// centre, by the midpoint rule with m points per diameter along each axis.
DoubleMoments midpointMoments(double radius, double above, int m) {
  const double step = 2.0 * radius / m, cell = step * step * step;
  DoubleMoments sum;
  for (int k = 0; k < m; ++k) {
    const double y = -radius + (k + 0.5) * step;
    if (y >= above) continue;
    for (int j = 0; j < m; ++j) {
      const double z = -radius + (j + 0.5) * step;
      for (int i = 0; i < m; ++i) {
        const double x = -radius + (i + 0.5) * step;
        if (x * x + y * y + z * z > radius * radius) continue;
        sum.volume += cell;
        sum.variance += x * x * cell;
        sum.meanDepth += (above - y) * cell;
      }
    }
  }
  sum.variance /= sum.volume;
  sum.meanDepth /= sum.volume;
  return sum;
}

// The Gaussian bump's volume over [lo, hi], no walls, by the midpoint rule.
double midpointBump(glm::dvec2 lo, glm::dvec2 hi, glm::dvec2 c, double sigma, double volume, int m) {
  const double dx = (hi.x - lo.x) / m, dz = (hi.y - lo.y) / m;
  double sum = 0.0;
  for (int b = 0; b < m; ++b) {
    for (int a = 0; a < m; ++a) {
      const double x = lo.x + (a + 0.5) * dx - c.x, z = lo.y + (b + 0.5) * dz - c.y;
      sum += std::exp(-(x * x + z * z) / (2.0 * sigma * sigma));
    }
  }
  return volume * sum * dx * dz / (2.0 * glm::pi<double>() * sigma * sigma);
}

// The bump of a sphere that moves slower than the waves (fast 0) or well
// past them (fast 1), its variance times `widening` (near the wave speed).
double gridVolume(uint32_t n, float length, glm::vec3 c, float radius, float level, bool wrap, float fast = 0.0f,
                  float widening = 1.0f) {
  return sumOverCells(n, length, [&](glm::vec2 lo, glm::vec2 hi) {
    return shader::sphereSpreadVolume(lo, hi, c, radius, level, length, kDepthFactor, wrap, widening, fast,
                                      float(sim::kSpreadTopShare));
  });
}

float slowDeviation(const shader::SubmergedMoments& m) { return std::sqrt(shader::spreadVariance(m, kDepthFactor)); }

}  // namespace

// From a thin cap to a ball well under the level. Measured worst relative
// error at 240 points per diameter: volume 5e-5, variance 1e-4, mean depth
// 3e-4 (the midpoint rule's, at the thin cap).
TEST(SphereSpread, SubmergedMomentsMatchAMidpointRuleOverTheBall) {
  const double radius = 0.45;
  for (const double depthInRadii : {0.3, 1.0, 1.4, 2.0, 3.5}) {  // of the sphere's bottom below the level
    const double depth = depthInRadii * radius;
    const shader::SubmergedMoments m = shader::submergedMoments(float(radius), float(depth));
    const DoubleMoments want = midpointMoments(radius, depth - radius, 240);
    std::printf("bottom %.2f r under: volume %.6f (%.6f), variance %.6f (%.6f), mean depth %.6f (%.6f)\n", depthInRadii,
                m.volume, want.volume, m.variance, want.variance, m.meanDepth, want.meanDepth);
    EXPECT_NEAR(m.volume, want.volume, 2e-3 * want.volume);
    EXPECT_NEAR(m.variance, want.variance, 1e-3 * want.variance);
    EXPECT_NEAR(m.meanDepth, want.meanDepth, 1e-3 * want.meanDepth);
    EXPECT_NEAR(m.volume, sim::sphereCapVolume(radius, 0.0, depth - radius), 1e-6 * want.volume);
  }
  const shader::SubmergedMoments dry = shader::submergedMoments(0.45f, -0.1f);
  EXPECT_EQ(dry.volume, 0.0f);
}

// Measured worst absolute error: 1.6e-7, float's rounding on the fit's own
// bound of 1.5e-7 in erf.
TEST(SphereSpread, NormalTailMatchesErfc) {
  double worst = 0.0;
  for (double u = 0.0; u <= 8.0; u += 0.01) {
    const double exact = 0.5 * std::erfc(u / std::sqrt(2.0));
    worst = std::max(worst, std::abs(double(shader::normalTail(float(u))) - exact));
  }
  std::printf("worst normal tail error: %.2e\n", worst);
  EXPECT_LT(worst, 2e-7);
  EXPECT_EQ(shader::normalTail(8.5f), 0.0f);
}

// Each column against a fine midpoint rule over the bump's density on its
// square, away from the walls, for a sphere half in and one well under.
// Measured worst error: 3e-8 of the sphere's volume.
TEST(SphereSpread, ColumnsMatchAMidpointRuleOverTheBump) {
  const float radius = 0.45f, length = 4.0f, level = 0.0f, h = 4.0f / 64.0f;
  for (const float centreY : {0.0f, -0.8f}) {
    const glm::vec3 c(2.013f, centreY, 1.971f);
    const shader::SubmergedMoments m = shader::submergedMoments(radius, level - centreY + radius);
    const double sigma = slowDeviation(m);
    double worst = 0.0;
    for (uint32_t j = 20; j < 44; j += 3) {
      for (uint32_t i = 20; i < 44; i += 3) {
        const glm::vec2 lo(float(i) * h, float(j) * h), hi(float(i + 1) * h, float(j + 1) * h);
        const double got = shader::sphereSpreadVolume(lo, hi, c, radius, level, length, kDepthFactor, false, 1.0f, 0.0f,
                                                      float(sim::kSpreadTopShare));
        const double want = midpointBump(lo, hi, glm::dvec2(c.x, c.z), sigma, m.volume, 64);
        worst = std::max(worst, std::abs(got - want) / m.volume);
      }
    }
    std::printf("centre at %.2f: worst column error %.2e of the volume\n", centreY, worst);
    EXPECT_LT(worst, 1e-6);
  }
}

// Over a whole grid the columns hold the submerged volume: in the middle,
// touching a wall (the part of the bump beyond it mirrored back) and across
// a wrapped edge, slower than the waves and faster, widened near the wave
// speed and wider than the pool itself. Measured worst relative
// error: 4.3e-7 (float sums of 512^2 columns).
TEST(SphereSpread, ColumnsAddUpToTheSubmergedVolume) {
  const float length = 4.0f, level = 0.0f;
  double worst = 0.0;
  for (const uint32_t n : {32u, 128u, 512u}) {
    for (const float radius : {0.05f, 0.45f}) {
      for (const float centreY : {0.3f, 0.0f, -0.6f}) {
        for (const float x : {2.013f, radius + 0.01f, length - radius - 0.01f}) {
          for (const bool wrap : {false, true}) {
            // Slow, fast, widened near the wave speed as far as it goes, and
            // wider than the pool (the bump's further images folded in).
            for (const auto& [fast, widening] :
                 {std::pair(0.0f, 1.0f), std::pair(1.0f, 1.0f),
                  std::pair(0.0f, float(sim::wakeWidening(sim::kWakeCapFroude))), std::pair(0.0f, 400.0f)}) {
              const glm::vec3 c(x, centreY * radius / 0.45f, 1.971f);
              const double exact = sim::sphereCapVolume(radius, c.y, level);
              const double sum = gridVolume(n, length, c, radius, level, wrap, fast, widening);
              worst = std::max(worst, std::abs(sum - exact) / exact);
            }
          }
        }
      }
    }
  }
  std::printf("worst relative error of a grid's columns: %.2e\n", worst);
  EXPECT_LT(worst, 2e-6);
}

// A ball pushed through a wall displaces only its part inside the pool, as
// the column forcing's columns measure it (which integrate the ball over
// the grid's squares, tests/sphere_column_test.cpp), and nothing once it is
// through. Measured worst difference: 2.9e-7 of the ball's volume.
TEST(SphereSpread, ABallThroughAWallDisplacesItsPartInside) {
  const float radius = 0.45f, length = 4.0f, level = 0.0f;
  const uint32_t n = 128;
  const double ball = 4.0 / 3.0 * glm::pi<double>() * radius * radius * radius;
  double worst = 0.0;
  for (const float x : {0.3f, 0.0f, -0.2f, 3.8f, 4.4f}) {
    const glm::vec3 c(x, -0.6f, 2.013f);
    const double columns = sumOverCells(
        n, length, [&](glm::vec2 lo, glm::vec2 hi) { return shader::sphereColumnVolume(lo, hi, c, radius, level); });
    const double spread = gridVolume(n, length, c, radius, level, false);
    std::printf("ball at x %.2f: spread %.6f, columns %.6f m^3\n", x, spread, columns);
    worst = std::max(worst, std::abs(spread - columns) / ball);
  }
  std::printf("worst difference: %.2e of the ball's volume\n", worst);
  EXPECT_LT(worst, 1e-5);
  EXPECT_EQ(gridVolume(n, length, {-0.46f, -0.6f, 2.0f}, radius, level, false), 0.0);
}

// A sphere moving by a tiny step changes each column by a bounded amount
// per metre, on any grid and as the step shrinks: the bump has no edge (the
// column forcing's rate grows as the cell shrinks). The bound is the bump's
// steepest slope, volume / (2 pi sigma^2) / (sigma sqrt(e)), 1.55 for a
// sphere of 0.45 m half in. Measured: 1.498 on 64 cells, 1.532 on 512 at a
// step of 1 mm (1.558 at 0.1 mm, float's rounding of the difference).
TEST(SphereSpread, ColumnsChangeSmoothlyAsTheSphereMoves) {
  const float radius = 0.45f, length = 4.0f;
  const shader::SubmergedMoments m = shader::submergedMoments(radius, radius);
  const double sigma = slowDeviation(m);
  const double steepest = m.volume / (2.0 * glm::pi<double>() * sigma * sigma) / (sigma * std::sqrt(std::exp(1.0)));
  for (const uint32_t n : {64u, 512u}) {
    const float h = length / float(n);
    for (const float step : {1e-3f, 1e-4f}) {
      double worstRate = 0.0;
      for (uint32_t i = 0; i < n; ++i) {
        const glm::vec2 lo(float(i) * h, 2.0f), hi(float(i + 1) * h, 2.0f + h);
        const float before = shader::sphereSpreadVolume(lo, hi, {2.0f, 0.0f, 2.0f}, radius, 0.0f, length, kDepthFactor,
                                                        false, 1.0f, 0.0f, float(sim::kSpreadTopShare));
        const float after = shader::sphereSpreadVolume(lo, hi, {2.0f + step, 0.0f, 2.0f}, radius, 0.0f, length,
                                                       kDepthFactor, false, 1.0f, 0.0f, float(sim::kSpreadTopShare));
        worstRate = std::max(worstRate, std::abs(double(after) - double(before)) / (step * h * h));
      }
      std::printf("%u cells, step %.0e m: largest height change per metre moved %.4f (the bump's slope %.4f)\n", n,
                  step, worstRate, steepest);
      EXPECT_LT(worstRate, 1.03 * steepest);
      if (n == 512u && step == 1e-3f) {
        EXPECT_GT(worstRate, 0.97 * steepest);
      }
    }
  }
}

// Faster than the waves the bump stands where it is put, so its peak is kept
// to kSpreadTopShare of the sphere's top over the level: the highest column
// of a fine grid (each column's mean over its square, just under the
// Gaussian's peak) against that height, for spheres from half in to mostly
// out (whose bump is low enough unwidened). Slower than the waves the same bump may stand over the top (the
// default half-in sphere's by 0.11 m). And the widening fades as the top
// sinks to the level: just over it, the bump is the slow one.
TEST(SphereSpread, AFastSphereLiftsItsWaterNoHigherThanItsTop) {
  const float radius = 0.4f, length = 4.0f, level = 0.0f, share = float(sim::kSpreadTopShare);
  const uint32_t n = 512;
  const float h = length / float(n);
  const auto highest = [&](glm::vec3 c, float fast) {
    double top = 0.0;
    for (uint32_t j = 0; j < n; ++j) {
      for (uint32_t i = 0; i < n; ++i) {
        const glm::vec2 lo(float(i) * h, float(j) * h), hi(float(i + 1) * h, float(j + 1) * h);
        top = std::max(top, double(shader::sphereSpreadVolume(lo, hi, c, radius, level, length, kDepthFactor, false,
                                                              1.0f, fast, share)) /
                                (double(h) * h));
      }
    }
    return top;
  };
  for (const float centreY : {0.0f, 0.1f, 0.25f}) {  // half in, and more of it out
    const glm::vec3 c(2.0f, centreY, 2.0f);
    const double sphereTop = double(centreY + radius - level);
    const double fast = highest(c, 1.0f), slow = highest(c, 0.0f);
    std::printf("centre %.2f over the level: top %.3f m, the bump's peak %.4f m fast, %.4f m slow\n", centreY,
                sphereTop, fast, slow);
    EXPECT_LE(fast, share * sphereTop);
    if (slow > share * sphereTop) {
      EXPECT_GT(fast, 0.99 * share * sphereTop);  // widened no more than it must be
    } else {
      EXPECT_EQ(fast, slow);  // low enough as it is
    }
  }
  EXPECT_GT(highest({2.0f, 0.0f, 2.0f}, 0.0f), double(radius));

  const float justUnder = -radius + 1e-4f * radius;  // the top 1e-4 r over the level
  const shader::SubmergedMoments m = shader::submergedMoments(radius, level - justUnder + radius);
  const float slowVariance = shader::spreadVariance(m, kDepthFactor);
  const float fastVariance =
      shader::fastSpreadVariance(m, slowVariance, radius, justUnder + radius - level, 1.0f, share);
  std::printf("top 1e-4 r over the level: variance %.6e fast, %.6e slow\n", fastVariance, slowVariance);
  EXPECT_NEAR(fastVariance, slowVariance, 1e-3 * slowVariance);
}

}  // namespace tp::test
