// A sphere crossing the pool (sim/wake_run.hpp) on lavapipe under
// validation: the wake it leaves is smooth, converges as the grid is refined,
// keeps the water's volume, and a sphere fully under the surface still moves
// it. The figures the tests see are printed; docs/water-numerics.md has them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "shared/sphere_spread.h"
#include "sim/gpu_stepper.hpp"
#include "sim/steady_wake.hpp"
#include "sim/wake_run.hpp"

namespace tp::test {
namespace {

void print(const sim::WakeCase& c, const sim::WakeResult& r) {
  std::printf(
      "%s  grid %4u  %.1f c  %-9s  high %.4f  slope %6.3f  crest %.4f  trough %.4f  volume change %.2e of %.3f\n",
      sim::toString(c.forcing).c_str(), c.grid, c.speedFraction, c.submerged ? "submerged" : "half in",
      r.measures.highShare, r.measures.maxSlope, r.measures.crest, r.measures.trough, r.volumeChange,
      r.submergedVolume);
}

// What the spread forcing (shared/sphere_spread.h, as water_sphere.comp
// evaluates it) adds to each cell of `p`'s grid for a sphere of `radius`
// standing at `centre` in water resting at 0: its volume there over the
// cell's area. `fast`: fastSpreadVariance's (0 slower than the waves);
// `widening`: the factor on its variance near the wave speed (1 slower).
std::vector<double> spreadHeights(const sim::WaterParams& p, glm::vec3 centre, float radius, float fast = 0.0f,
                                  float widening = 1.0f) {
  const float h = float(p.h());
  const double area = double(h) * double(h);
  std::vector<double> heights(size_t(p.n) * p.n);
  for (uint32_t j = 0; j < p.n; ++j) {
    for (uint32_t i = 0; i < p.n; ++i) {
      const glm::vec2 lo(float(i) * h, float(j) * h), hi(float(i + 1) * h, float(j + 1) * h);
      heights[size_t(j) * p.n + i] =
          double(shader::sphereSpreadVolume(lo, hi, centre, radius, 0.0f, float(p.extent), float(p.spreadDepthFactor),
                                            p.boundary == sim::Boundary::Wrap, widening, fast,
                                            float(sim::kSpreadTopShare))) /
          area;
    }
  }
  return heights;
}

// How far the water stands over the top of the sphere at the end of `r`'s
// crossing, within half its radius of its centre (negative: under it).
double waterOverSphere(const sim::WakeCase& c, const sim::WakeResult& r) {
  const uint32_t n = r.state.n;
  const double h = c.extent / n, radius = c.radius;
  double worst = -std::numeric_limits<double>::infinity();
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const double dx = (i + 0.5) * h - r.endCentre.x, dz = (j + 0.5) * h - r.endCentre.z;
      const double rho2 = dx * dx + dz * dz;
      if (rho2 > 0.25 * radius * radius) continue;
      const double top = r.endCentre.y + std::sqrt(radius * radius - rho2);
      worst = std::max(worst, double(r.state.u[size_t(j) * n + i]) - top);
    }
  }
  return worst;
}

// The crossing at 0.5 c (1.4 m, half in) on 128, 256 and 512 cells with
// `forcing`, the water's volume kept to round-off on each: how much the
// wake differs between successive grids, coarse over fine.
double refinementRatio(const gpu::Context& ctx, sim::SphereForcing forcing) {
  std::vector<sim::WakeResult> results;
  for (const uint32_t grid : {128u, 256u, 512u}) {
    const sim::WakeCase c{.grid = grid, .speedFraction = 0.5, .forcing = forcing, .crossing = 1.4};
    results.push_back(sim::runWake(ctx, c));
    print(c, results.back());
    EXPECT_LT(std::abs(results.back().volumeChange), 1e-5 * results.back().submergedVolume);
  }
  const double coarse = sim::rmsDifference(results[0].state, results[1].state);
  const double fine = sim::rmsDifference(results[1].state, results[2].state);
  std::printf("%s: rms difference 128-256: %.3e m, 256-512: %.3e m, ratio %.2f\n", sim::toString(forcing).c_str(),
              coarse, fine, coarse / fine);
  return coarse / fine;
}

// Runs `c` and checks what docs/water-numerics.md claims of it: under 2% of
// the height variance above half the Nyquist wavenumber at every speed and
// immersion with either forcing (the old centre-sampled forcing left 26-41%),
// and the water's volume kept. The spread forcing keeps the steepest slope
// under 1 and the crest under 0.1 m at every speed, half in or wholly
// under (at 0.9 c with its bump widened near the wave speed,
// sim::wakeWidening); the column forcing keeps the crest under 0.1 m at
// 0.2 c and the slope under 1 at 0.2 c (half in on every grid, under up to
// 128 cells) and, half in, at 0.5 c on 64 (1.04 on 128: its waterline's
// slope grows as the grid is refined). At 0.9 c the column forcing's crest
// is the wave equation's answer to a body moving near the wave speed (the
// steady wake's, below), and at its waterline the slope is the chord's:
// only the smoothness is asserted there.
void expectSmooth(const gpu::Context& ctx, const sim::WakeCase& c) {
  const sim::WakeResult r = sim::runWake(ctx, c);
  print(c, r);
  SCOPED_TRACE(sim::toString(c.forcing) + ", " + std::to_string(c.grid) + " cells, " + std::to_string(c.speedFraction) +
               " c" + (c.submerged ? ", submerged" : ", half in"));
  EXPECT_LT(r.measures.highShare, 0.02);
  EXPECT_LT(std::abs(r.volumeChange), 1e-5 * r.submergedVolume);
  const bool spread = c.forcing == sim::SphereForcing::Spread;
  const bool columnSlopeBound = (c.speedFraction == 0.2 && (c.grid <= 128 || !c.submerged)) ||
                                (c.speedFraction == 0.5 && !c.submerged && c.grid == 64);
  if (spread || columnSlopeBound) {
    EXPECT_LT(r.measures.maxSlope, 1.0);
  }
  if (spread || c.speedFraction == 0.2) {
    EXPECT_LT(r.measures.crest, 0.1);
  }
}

}  // namespace

using Wake = GpuTest;

// The default crossing (2.8 m) on grids of 64 and 128 cells, with either
// forcing, at 0.2, 0.5 and 0.9 c, half in and wholly under.
TEST_F(Wake, SmoothAtEverySpeedAndImmersion) {
  for (const sim::SphereForcing forcing : {sim::SphereForcing::Column, sim::SphereForcing::Spread}) {
    for (const uint32_t grid : {64u, 128u}) {
      for (const double speed : {0.2, 0.5, 0.9}) {
        for (const bool submerged : {false, true}) {
          expectSmooth(ctx(), {.grid = grid, .speedFraction = speed, .submerged = submerged, .forcing = forcing});
        }
      }
    }
  }
}

// The same on 256 and 512 cells, over half the crossing (1.4 m) to keep the
// run short: either forcing on 256, the scenes' spread forcing on 512.
TEST_F(Wake, SmoothOnFineGrids) {
  for (const sim::SphereForcing forcing : {sim::SphereForcing::Column, sim::SphereForcing::Spread}) {
    for (const uint32_t grid : {256u, 512u}) {
      if (grid == 512 && forcing == sim::SphereForcing::Column) continue;
      for (const double speed : {0.2, 0.5, 0.9}) {
        for (const bool submerged : {false, true}) {
          expectSmooth(
              ctx(),
              {.grid = grid, .speedFraction = speed, .submerged = submerged, .forcing = forcing, .crossing = 1.4});
        }
      }
    }
  }
}

// A sphere faster than the waves is not washed over by the water it lifts:
// the default sphere half in, crossing the default pool on 128 cells at
// 1.3, 2, 3 and 5 times the wave speed, stands above its water within half
// its radius of its centre (fastSpreadVariance; at 1.3 c mostly the
// widening near the wave speed, sim::wakeWidening, still easing out).
// Before the bump was widened above the wave speed, the water stood 0.20,
// 0.12, 0.10 and 0.11 m over its top.
TEST_F(Wake, AFastSphereStandsAboveItsWater) {
  for (const double speed : {1.3, 2.0, 3.0, 5.0}) {
    const sim::WakeCase c{.speedFraction = speed, .forcing = sim::SphereForcing::Spread};
    const sim::WakeResult r = sim::runWake(ctx(), c);
    print(c, r);
    const double over = waterOverSphere(c, r);
    std::printf("%.1f c: the water stands %.4f m over the sphere's top\n", speed, over);
    EXPECT_LT(std::abs(r.volumeChange), 1e-5 * r.submergedVolume);
    EXPECT_LT(over, 0.0) << speed << " c";
  }
}

// The column forcing's wake converges (measured: the difference between
// successive grids falls by 1.54 with the default kappa 2; the chord's
// vertical edge at the waterline keeps the order low, about a half).
TEST_F(Wake, ConvergesAsTheGridIsRefinedAndKeepsTheVolume) {
  EXPECT_GT(refinementRatio(ctx(), sim::SphereForcing::Column), 1.25);
}

// The slope limiter (water.max_slope) keeps the water's volume where the
// wake is steepest, the spread forcing's crossing at 0.9 c half in (the
// clamp it replaced gained 0.075 m^3 at a limit of 1 and 0.87 m^3 at 0.25,
// beside the sphere's 0.134 m^3), and lowers the steepest slope. The bump
// is not widened near the wave speed here, so that the wake is as steep as
// the attempts in docs/water-numerics.md met it.
TEST_F(Wake, SlopeLimiterKeepsTheVolume) {
  const sim::WakeCase free{.speedFraction = 0.9, .forcing = sim::SphereForcing::Spread, .widenNearWaveSpeed = false};
  const sim::WakeResult unlimited = sim::runWake(ctx(), free);
  print(free, unlimited);
  for (const double maxSlope : {1.0, 0.25}) {
    sim::WakeCase limited = free;
    limited.maxSlope = maxSlope;
    const sim::WakeResult r = sim::runWake(ctx(), limited);
    std::printf("max_slope %.2f: ", maxSlope);
    print(limited, r);
    SCOPED_TRACE("max slope " + std::to_string(maxSlope));
    EXPECT_LT(std::abs(r.volumeChange), 1e-5 * r.submergedVolume);
    EXPECT_LT(r.measures.maxSlope, 0.9 * unlimited.measures.maxSlope);
  }
}

// A sphere resting half in the water leaves still water still, to the bit,
// with either forcing.
TEST_F(Wake, RestingSphereLeavesStillWaterStill) {
  for (const sim::SphereForcing forcing : {sim::SphereForcing::Column, sim::SphereForcing::Spread}) {
    const sim::WaterParams p{
        .n = 128, .extent = 4.0, .waveSpeed = 0.6, .damping = 0.3, .gridDamping = 2.0, .sphereForcing = forcing};
    sim::GpuStepper stepper(ctx(), p, sim::flatState(p.n), sim::StepKernel::ActiveTiles);
    const glm::vec3 centre(1.7f, 0.0f, 2.3f);
    gpu::submitAndWait(
        ctx(),
        [&](const vk::raii::CommandBuffer& cmd) {
          for (int s = 0; s < 100; ++s) {
            stepper.recordSphereMove(cmd, centre, centre, 0.45f, 0.0f, 1.0 / 60.0);
            stepper.recordSteps(cmd, 1, 1.0 / 60.0);
          }
        },
        "resting sphere");
    const sim::WaterState state = stepper.download();
    for (size_t k = 0; k < state.u.size(); ++k) {
      ASSERT_EQ(state.u[k], 0.0f) << sim::toString(forcing) << ", cell " << k;
      ASSERT_EQ(state.v[k], 0.0f) << sim::toString(forcing) << ", cell " << k;
    }
  }
}

// Undamped, with short steps, the steady wake over a round Gaussian bump's
// centre converges to the continuous equation's trough, -(1 / sqrt(1 - F^2)
// - 1) times the bump's peak, as the grid is refined (measured on a 16 m
// square: 1.1% and 2.4% off on 128 cells at 0.5 c and 0.9 c, 0.7% and 0.9%
// on 256); a grid with walls and a bump of the wrong size are refused.
TEST(SteadyWake, UndampedTroughConvergesToTheClosedForm) {
  const double extent = 16.0, sigma = 0.5, peak = 0.3;
  for (const double f : {0.5, 0.9}) {
    const double want = -(1.0 / std::sqrt(1.0 - f * f) - 1.0) * peak;
    std::vector<double> errors;
    for (const uint32_t n : {128u, 256u}) {
      const sim::WaterParams p{.n = n, .extent = extent, .waveSpeed = 0.6, .boundary = sim::Boundary::Wrap};
      const double h = p.h();
      std::vector<double> bump(size_t(n) * n);
      for (uint32_t j = 0; j < n; ++j) {
        for (uint32_t i = 0; i < n; ++i) {
          const double x = (i + 0.5) * h - 0.5 * extent, z = (j + 0.5) * h - 0.5 * extent;
          bump[size_t(j) * n + i] = peak * std::exp(-(x * x + z * z) / (2.0 * sigma * sigma));
        }
      }
      const std::vector<double> u = sim::steadyWake(p, 1e-3, f * p.waveSpeed, bump);
      const uint32_t m = n / 2;  // the bump is centred on the corner of cells m - 1 and m
      const double centre =
          (u[size_t(m) * n + m] + u[size_t(m - 1) * n + m - 1] + u[size_t(m - 1) * n + m] + u[size_t(m) * n + m - 1]) /
          4.0;
      errors.push_back(std::abs(centre / want - 1.0));
      std::printf("%.1f c, %u cells: trough %.5f m, closed form %.5f m\n", f, n, centre, want);
    }
    EXPECT_LT(errors[1], 0.01);
    EXPECT_LT(errors[1], errors[0] / 1.5);
  }
  const std::vector<double> bump(size_t(64) * 64, 0.0);
  EXPECT_THROW(sim::steadyWake({.n = 64, .extent = 16.0}, 1e-3, 0.3, bump), std::invalid_argument);
  EXPECT_THROW(sim::steadyWake({.n = 64, .boundary = sim::Boundary::Wrap}, 1e-3, 0.3, std::vector<double>(10)),
               std::invalid_argument);
}

// Past half the wave speed the spread bump is widened (sim::wakeWidening)
// so that the wake deepens no further: the steady wake of the default
// sphere, half in or wholly under, solved mode by mode on a 16 m square of
// 256 cells with the scenes' water, at speeds from 0.6 c to 0.95 c. Its
// trough is no deeper than at 0.5 c, and its crest at most 1.5 times as
// high (measured: 1.39 at most, half in at 0.8 c), where the unwidened
// bump's grow up to 12.5 and 8.7 times. Above kWakeCapFroude the widening
// is held, and it eases out above the wave speed: it has no jump there.
TEST(SteadyWake, TheWidenedBumpKeepsTheWakeOfHalfTheWaveSpeed) {
  const sim::WakeCase c{
      .grid = 256, .forcing = sim::SphereForcing::Spread, .boundary = sim::Boundary::Wrap, .extent = 16.0};
  const sim::WaterParams p = sim::waterParams(c);
  const double dt = c.frameTime / sim::substepsFor(p, c.frameTime), radius = c.radius;
  for (const bool submerged : {false, true}) {
    const glm::vec3 centre(8.0f, float(submerged ? -(radius + sim::kSubmergedClearance) : 0.0), 8.0f);
    const auto wake = [&](double froude, double widening) {
      const std::vector<double> bump = spreadHeights(p, centre, float(radius), 0.0f, float(widening));
      const std::vector<double> u = sim::steadyWake(p, dt, froude * p.waveSpeed, bump);
      const auto [low, high] = std::minmax_element(u.begin(), u.end());
      return std::pair(*high, -*low);
    };
    const auto [crest0, trough0] = wake(sim::kWakeFroude, 1.0);
    for (const double froude : {0.6, 0.7, 0.8, 0.9, 0.95}) {
      const auto [crest, trough] = wake(froude, sim::wakeWidening(froude));
      const auto [bareCrest, bareTrough] = wake(froude, 1.0);
      std::printf("%s, %.2f c: crest %.4f m, trough %.4f m (at 0.5 c: %.4f, %.4f; unwidened: %.4f, %.4f)\n",
                  submerged ? "under" : "half in", froude, crest, trough, crest0, trough0, bareCrest, bareTrough);
      SCOPED_TRACE(std::to_string(froude) + (submerged ? " c, under" : " c, half in"));
      EXPECT_LT(crest, 1.5 * crest0);
      EXPECT_LT(trough, trough0);
    }
  }
  EXPECT_EQ(sim::wakeWidening(0.3), 1.0);
  EXPECT_EQ(sim::wakeWidening(sim::kWakeFroude), 1.0);
  const double held = sim::wakeWidening(sim::kWakeCapFroude);
  EXPECT_NEAR(sim::wakeWidening(std::nextafter(sim::kWakeCapFroude, 0.0)), held, 1e-9 * held);
  EXPECT_EQ(sim::wakeWidening(1.0), held);
  EXPECT_NEAR(sim::wakeWidening(1.25), 0.5 * (1.0 + held), 1e-12 * held);
  EXPECT_EQ(sim::wakeWidening(sim::kFastFroude), 1.0);
  EXPECT_EQ(sim::wakeWidening(std::numeric_limits<double>::infinity()), 1.0);
}

// A sphere circling a grid that wraps round at 0.5 c and 0.9 c, half in or
// wholly under, settles into the steady wake (sim/steady_wake.hpp): the
// linear step's exact answer for a bump moving at a constant speed, solved
// mode by mode. The start's waves fade as e^(-gamma t / 2): after 60 s at
// the scenes' 0.3/s, e^-9 of them are left. The wake is a trough over the
// sphere with crests before and after it, not a mound. Its crest, trough
// and slope (outside a half-in sphere's waterline, as bench wake measures)
// are printed: docs/water-numerics.md quotes them.
TEST_F(Wake, CrossingSettlesIntoTheSteadyWake) {
  for (const double speed : {0.5, 0.9}) {
    for (const bool submerged : {false, true}) {
      const sim::WakeCase c{.grid = 128,
                            .speedFraction = speed,
                            .submerged = submerged,
                            .forcing = sim::SphereForcing::Spread,
                            .boundary = sim::Boundary::Wrap,
                            .extent = 8.0,
                            .crossing = 60.0 * speed * 0.6};
      const sim::WakeResult r = sim::runWake(ctx(), c);
      const sim::WaterParams p = sim::waterParams(c);
      const double h = p.h();
      const std::vector<double> bump =
          spreadHeights(p, r.endCentre, float(c.radius), 0.0f, float(sim::wakeWidening(speed)));
      const std::vector<double> steady = sim::steadyWake(p, r.dt, speed * c.waveSpeed, bump);
      sim::WaterState steadyState{.n = c.grid, .u = std::vector<float>(steady.begin(), steady.end()), .v = {}};
      std::vector<sim::WaterlineDisc> hidden;
      if (!submerged) hidden.push_back({double(r.endCentre.x), double(r.endCentre.z), c.radius});
      const sim::WakeMeasures m = sim::measureWake(steadyState, c.extent, 0.0, hidden);
      double worst = 0.0, highest = 0.0, lowest = 0.0;
      for (size_t k = 0; k < steady.size(); ++k) {
        worst = std::max(worst, std::abs(double(r.state.u[k]) - steady[k]));
        highest = std::max(highest, steady[k]);
        lowest = std::min(lowest, steady[k]);
      }
      const double over = steady[size_t(r.endCentre.z / h) * c.grid + size_t(r.endCentre.x / h)];
      std::printf(
          "%.1f c, %-9s steady wake: crest %.4f m, trough %.4f m, slope %.3f, over the sphere %.4f m; the GPU's "
          "worst difference %.2e m\n",
          speed, submerged ? "under:" : "half in:", m.crest, m.trough, m.maxSlope, over, worst);
      SCOPED_TRACE(std::to_string(speed) + " c" + (submerged ? ", under" : ", half in"));
      EXPECT_LT(worst, 1e-4 * (highest - lowest));  // measured: at most 2e-5 of it
      EXPECT_LT(over, 0.0);                         // a trough over the sphere
      EXPECT_GT(m.crest, 0.1 * m.trough);
    }
  }
}

// WebGL Water's oldest open issue: there, a sphere wholly under the surface
// moving sideways leaves the water flat. Here its wake has a crest and a
// trough of centimetres, as smooth as the half-in sphere's, with either
// forcing (measured: crest 0.044 and 0.025 m, trough 0.043 and 0.015 m).
TEST_F(Wake, SubmergedSphereMovingSidewaysMovesTheWater) {
  for (const sim::SphereForcing forcing : {sim::SphereForcing::Column, sim::SphereForcing::Spread}) {
    const sim::WakeCase c{.grid = 128, .speedFraction = 0.3, .submerged = true, .forcing = forcing, .crossing = 1.4};
    const sim::WakeResult r = sim::runWake(ctx(), c);
    print(c, r);
    EXPECT_GT(r.measures.crest, 0.01);
    EXPECT_GT(r.measures.trough, 0.005);
    EXPECT_LT(r.measures.highShare, 0.02);
  }
}

// The spread forcing's wake converges faster than the column forcing's,
// having no edge at the waterline (measured: 2.51).
TEST_F(Wake, SpreadForcingConvergesAsTheGridIsRefined) {
  EXPECT_GT(refinementRatio(ctx(), sim::SphereForcing::Spread), 2.0);
}

// What the GPU adds to the water for one move of the sphere is what the
// shared header gives in C++, cell by cell, with the walls mirrored and with
// the grid wrapped round, with the free surface's widening and a wider one
// (bench wake's), for a move slower than the waves (over a second) and one
// faster (at once: the bump widened all the way), and one at 0.9 of the
// wave speed (its variance times sim::wakeWidening), and a sphere at rest
// changes nothing.
TEST_F(Wake, SpreadForcingOnTheGpuIsTheHeadersVolume) {
  enum class Pace { Slow, NearTheWaves, Fast };
  for (const sim::Boundary boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    for (const double widening : {sim::kSpreadDepthFactor, 3.0}) {
      for (const Pace pace : {Pace::Slow, Pace::NearTheWaves, Pace::Fast}) {
        const sim::WaterParams p{.n = 64,
                                 .extent = 4.0,
                                 .waveSpeed = 0.6,
                                 .boundary = boundary,
                                 .sphereForcing = sim::SphereForcing::Spread,
                                 .spreadDepthFactor = widening};
        sim::GpuStepper stepper(ctx(), p, sim::flatState(p.n), sim::StepKernel::OnePerDispatch);
        const glm::vec3 from(0.31f, -0.2f, 2.1f), to(0.36f, -0.15f, 2.1f);
        const double froude = 0.9, across = double(to.x - from.x);
        const double seconds = pace == Pace::Slow ? 1.0 : pace == Pace::Fast ? 0.0 : across / (froude * p.waveSpeed);
        stepper.moveSphere(from, to, 0.45f, 0.0f, seconds);
        stepper.moveSphere(to, to, 0.45f, 0.0f, 0.0);
        const sim::WaterState state = stepper.download();
        const float weight = pace == Pace::Fast ? 1.0f : 0.0f;
        const float wider = pace == Pace::NearTheWaves ? float(sim::wakeWidening(froude)) : 1.0f;
        const std::vector<double> before = spreadHeights(p, from, 0.45f, weight, wider),
                                  after = spreadHeights(p, to, 0.45f, weight, wider);
        // The float round-off of each cell's volume does not shrink with the
        // change a short move makes (measured: 6e-7 to 8.5e-7 m in all four
        // cases): the bound is absolute, 2e-6 m (30 float ulps of the default
        // bump's 0.66 m), 500 times below the smallest peak change allowed.
        double worst = 0.0, peak = 0.0, bump = 0.0;
        for (size_t k = 0; k < after.size(); ++k) {
          const double want = after[k] - before[k];
          worst = std::max(worst, std::abs(double(state.u[k]) - want));
          peak = std::max(peak, std::abs(want));
          bump = std::max(bump, after[k]);
        }
        std::printf("%s, widening %.3g, %s: worst difference %.2e m of a peak change of %.2e m, a bump of %.2e m\n",
                    sim::toString(boundary).c_str(), widening,
                    pace == Pace::Slow   ? "slow"
                    : pace == Pace::Fast ? "fast"
                                         : "0.9 c",
                    worst, peak, bump);
        EXPECT_GT(peak, 1e-3);
        EXPECT_LT(worst, 2e-6);
      }
    }
  }
}

}  // namespace tp::test
