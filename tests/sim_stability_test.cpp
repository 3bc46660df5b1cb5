// Long runs: conservation, energy, and the stability bound.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/reference_sim.hpp"
#include "sim/wake_measures.hpp"
#include "sim_support.hpp"

namespace tp::test {

using SimStability = GpuTest;

// Sum of u, in double on the host from the downloaded state (independent of
// the GPU's own reduction): conserved to 1e-6 relative over 10^5 steps.
TEST_F(SimStability, VolumeIsConservedOver100000Steps) {
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    sim::WaterParams p{.n = 32, .extent = 1.0, .waveSpeed = 1.0, .boundary = boundary};
    const double dt = 0.5 * p.h();
    const auto initial = randomState(p.n, 1.0, 0.05, 3);
    sim::GpuStepper gpu(ctx(), p, initial, sim::StepKernel::Tiled, 8);
    const double v0 = volumeOf(initial, p.h());
    gpu.step(100000, dt);
    const auto end = gpu.download();
    EXPECT_LT(std::abs(volumeOf(end, p.h()) - v0) / v0, 1e-6) << sim::toString(boundary);
    // The GPU's reduction agrees with the host's sum.
    EXPECT_NEAR(gpu.stats(dt).volume, volumeOf(end, p.h()), 1e-6 * v0) << sim::toString(boundary);
  }
}

// lambda from 0.1 to 0.7 (just under 1/sqrt(2)), damping from none upward,
// white-noise fields, 10^5 steps, the health reduction every 1000: never a
// non-finite value; with damping the energy never grows; without it the
// symplectic scheme's energy stays within 1e-3 of its start.
TEST_F(SimStability, StressSweepOfLambdaAndDamping) {
  constexpr uint64_t kSteps = 100000, kCheckEvery = 1000;
  for (double lambda : {0.1, 0.4, 0.7}) {
    for (double gamma : {0.0, 0.5, 5.0}) {
      sim::WaterParams p{.n = 16,
                         .extent = 1.0,
                         .waveSpeed = 1.0,
                         .damping = gamma,
                         .boundary = lambda == 0.4 ? sim::Boundary::Wrap : sim::Boundary::Clamp};
      const double dt = lambda * p.h() / p.waveSpeed;
      sim::GpuStepper gpu(ctx(), p, randomState(p.n, 0.0, 0.1, uint32_t(lambda * 100 + gamma)), sim::StepKernel::Tiled,
                          8);
      const sim::WaterStats start = gpu.stats(dt);
      double previous = start.energy, worstDrift = 0.0;
      for (uint64_t done = 0; done < kSteps; done += kCheckEvery) {
        gpu.step(kCheckEvery, dt);
        const sim::WaterStats s = gpu.stats(dt);
        ASSERT_EQ(s.nonFinite, 0u) << "lambda " << lambda << " gamma " << gamma << " step " << done;
        if (gamma > 0.0) {
          // Allowance: float32 rounding of the sums (1e-6 relative), and the
          // quantisation floor of a float32 state, (8 eps)^2 of the start: once a
          // field has decayed to differences of a few ulps of its heights its
          // computed energy is that noise.
          ASSERT_LE(s.energy, previous * (1.0 + 1e-6) + 1e-12 * start.energy)
              << "lambda " << lambda << " gamma " << gamma << " step " << done;
        } else {
          worstDrift = std::max(worstDrift, std::abs(s.energy - start.energy) / start.energy);
        }
        previous = s.energy;
      }
      if (gamma == 0.0) {
        EXPECT_LT(worstDrift, 1e-3) << "lambda " << lambda;
      } else {
        EXPECT_LT(previous, 1e-6 * start.energy) << "lambda " << lambda;  // it did decay
      }
    }
  }
}

// The energy the stats report is the one the scheme conserves: the GPU's
// reduction agrees with the double-precision reference's.
TEST_F(SimStability, GpuEnergyMatchesReference) {
  sim::WaterParams p{.n = 40, .extent = 1.0, .waveSpeed = 1.0, .boundary = sim::Boundary::Wrap};
  const double dt = 0.6 * p.h();
  const auto initial = randomState(p.n, 0.0, 0.1, 5);
  sim::ReferenceSim reference(p, initial);
  reference.steps(10, dt);
  sim::GpuStepper gpu(ctx(), p, initial, sim::StepKernel::OnePerDispatch);
  gpu.step(10, dt);
  const auto g = gpu.stats(dt), r = reference.stats(dt);
  EXPECT_NEAR(g.energy, r.energy, 1e-4 * r.energy);
  EXPECT_NEAR(g.maxAbsU, r.maxAbsU, 1e-4 * r.maxAbsU);
  EXPECT_NEAR(g.maxAbsV, r.maxAbsV, 1e-4 * r.maxAbsV);
  EXPECT_NEAR(g.volume, r.volume, 1e-6);
}

// The literal forward Euler update is unstable for every dt without damping:
// its energy grows, and the health check stops the run instead of rendering garbage.
TEST_F(SimStability, ExplicitSchemeGrowsAndIsStopped) {
  sim::WaterParams p{.n = 16, .extent = 1.0, .waveSpeed = 1.0, .scheme = sim::Scheme::Explicit};
  const double dt = 0.3 * p.h();
  sim::GpuStepper gpu(ctx(), p, randomState(p.n, 0.0, 0.1, 9), sim::StepKernel::Tiled, 8);
  const double e0 = gpu.stats(dt).energy;
  gpu.step(60, dt);  // the checkerboard mode grows by about 1.3 a step here
  const sim::WaterStats grown = gpu.stats(dt);
  EXPECT_EQ(grown.nonFinite, 0u);
  EXPECT_TRUE(std::isfinite(grown.energy));
  EXPECT_GT(grown.energy, 100.0 * e0);
  gpu.step(20000, dt);
  const sim::WaterStats blown = gpu.stats(dt);
  EXPECT_GT(blown.nonFinite, 0u);
  EXPECT_THROW(sim::checkHealth(blown, 20200, 1e3), std::runtime_error);

  // The symplectic scheme at the same lambda stays bounded.
  p.scheme = sim::Scheme::Symplectic;
  sim::GpuStepper stable(ctx(), p, randomState(p.n, 0.0, 0.1, 9), sim::StepKernel::Tiled, 8);
  stable.step(2000, dt);
  EXPECT_LT(stable.stats(dt).energy, 1.01 * e0);
}

TEST(SimParams, LambdaOverTheBoundIsRefused) {
  sim::WaterParams p{.n = 100, .extent = 1.0, .waveSpeed = 2.0};
  const double dtAtBound = sim::kStabilityBound * p.h() / p.waveSpeed;
  EXPECT_NO_THROW(sim::checkStable(p, dtAtBound * (1.0 - 1e-12)));
  try {
    sim::checkStable(p, dtAtBound * 1.001);
    FAIL() << "lambda just over 1/sqrt(2) was accepted";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("lambda = c*dt/h = 0.70781"), std::string::npos) << m;
    EXPECT_NE(m.find("1/sqrt(2) = 0.707107"), std::string::npos) << m;
  }
  EXPECT_THROW(sim::checkStable(p, 0.0), std::runtime_error);
  EXPECT_THROW(sim::checkStable(p, std::nan("")), std::runtime_error);
}

// Without and with the slope limiter, whose bound on lambda is 1/2.
TEST(SimParams, SubstepsAreTheFewestWithinTheMargin) {
  sim::WaterParams p{.n = 256, .extent = 2.0, .waveSpeed = 0.5};
  for (const auto& [maxSlope, bound] : {std::pair{0.0, sim::kStabilityBound}, std::pair{0.5, 0.5}}) {
    p.maxSlope = maxSlope;
    for (double frame : {1.0 / 240, 1.0 / 60, 1.0 / 24, 0.5}) {
      const uint32_t k = sim::substepsFor(p, frame, 0.9);
      EXPECT_LE(p.lambda(frame / k), 0.9 * bound) << frame;
      if (k > 1) {
        EXPECT_GT(p.lambda(frame / (k - 1)), 0.9 * bound) << frame;
      }
    }
  }
  p.maxSlope = 0.0;
  EXPECT_THROW(sim::substepsFor(p, -1.0), std::runtime_error);
}

namespace {

// The largest |u| after 10^4 steps from a checkerboard of amplitude 1e-3, in
// the double-precision reference (written apart from the bounds); infinite
// once a value is not finite.
double checkerboardAfterManySteps(const sim::WaterParams& p, double dt) {
  sim::WaterState checkerboard = sim::flatState(p.n);
  for (uint32_t j = 0; j < p.n; ++j) {
    for (uint32_t i = 0; i < p.n; ++i) checkerboard.u[size_t(j) * p.n + i] = (i + j) % 2 ? 1e-3f : -1e-3f;
  }
  sim::ReferenceSim reference(p, checkerboard);
  reference.steps(10000, dt);
  double largest = 0.0;
  for (double u : reference.u()) largest = std::isfinite(u) ? std::max(largest, std::abs(u)) : INFINITY;
  return largest;
}

// A step of dt at `fraction` of a stability bound: just inside (< 1) the
// checkerboard stays bounded (within the scheme's transient growth, 27x at
// lambda 0.7) and checkStable accepts it; just outside it grows past a
// thousandfold and checkStable refuses it.
void expectSharpOnTheCheckerboard(const sim::WaterParams& p, double dt, double fraction) {
  if (fraction < 1.0) {
    EXPECT_LT(checkerboardAfterManySteps(p, dt), 0.1);
    EXPECT_NO_THROW(sim::checkStable(p, dt));
  } else {
    EXPECT_FALSE(checkerboardAfterManySteps(p, dt) < 1.0);
    EXPECT_THROW(sim::checkStable(p, dt), std::runtime_error);
  }
}

// The grid damping's bound for `p`, at each of `lambdas`, with and without
// damping: sharp on the checkerboard, 2% inside and 3% outside.
void expectGridDampingBoundSharp(sim::WaterParams p, std::initializer_list<double> lambdas) {
  for (const double lambda : lambdas) {
    for (const double damping : {0.0, 3.0}) {
      p.damping = damping;
      const double dt = lambda * p.h() / p.waveSpeed;
      for (const double fraction : {0.98, 1.03}) {
        p.gridDamping = fraction * sim::gridDampingBound(p, dt) / dt;
        SCOPED_TRACE("lambda " + std::to_string(lambda) + ", gamma " + std::to_string(damping) + ", fraction " +
                     std::to_string(fraction));
        expectSharpOnTheCheckerboard(p, dt, fraction);
      }
    }
  }
}

}  // namespace

// The grid damping's bound, 8 d lambda^2 + 16 kappa dt <= 2 + 2 d, is sharp
// on the checkerboard (the mode it binds on, sigma = 8 on an even periodic
// grid).
TEST(SimParams, GridDampingBoundIsSharpOnTheCheckerboard) {
  expectGridDampingBoundSharp({.n = 16, .extent = 1.0, .waveSpeed = 1.0, .boundary = sim::Boundary::Wrap},
                              {0.2, 0.5, 0.7});
}

// With the slope limiter on, the steep edges' share acts on the heights as a
// diffusion, and the bounds become lambda <= 1/2 and 8 d lambda^2 + 8 kappa
// dt <= 1 + d (share 1/8). Both are sharp on a checkerboard whose every edge
// is steep (its differences, 2e-3, far over the limit, 1e-6).
TEST(SimParams, SlopeLimiterBoundsAreSharpOnTheCheckerboard) {
  sim::WaterParams p{.n = 16, .extent = 1.0, .waveSpeed = 1.0, .boundary = sim::Boundary::Wrap};
  p.maxSlope = 1e-6 / p.h();
  EXPECT_DOUBLE_EQ(sim::lambdaBound(p), 0.5);
  for (const double fraction : {0.98, 1.03}) {
    SCOPED_TRACE("lambda at " + std::to_string(fraction) + " of its bound");
    expectSharpOnTheCheckerboard(p, fraction * sim::lambdaBound(p) * p.h() / p.waveSpeed, fraction);
  }
  expectGridDampingBoundSharp(p, {0.2, 0.45});
}

// The slope limiter moves water between neighbours and makes none: from white
// noise with steep edges everywhere, over 1000 steps, against walls and round
// a wrapped grid, the heights' sum holds to double round-off, while the
// steepest edge ends well under the free run's.
TEST(SimParams, SlopeLimiterKeepsTheVolume) {
  for (const auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    sim::WaterParams p{.n = 40, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.1, .boundary = boundary};
    const double dt = 0.4 * p.h() / p.waveSpeed;
    const auto initial = randomState(p.n, 0.0, 0.05, 3);
    sim::ReferenceSim free(p, initial);
    p.maxSlope = 0.2;
    sim::checkStable(p, dt);
    sim::ReferenceSim limited(p, initial);
    const double before = limited.stats(dt).volume;
    free.steps(1000, dt);
    limited.steps(1000, dt);
    auto steepest = [&](const sim::ReferenceSim& s) { return sim::measureWake(s.state(), p.extent, 0.0, {}).maxSlope; };
    SCOPED_TRACE(sim::toString(boundary));
    EXPECT_LT(std::abs(limited.stats(dt).volume - before), 1e-15);
    EXPECT_LT(steepest(limited), 0.5 * steepest(free));
    std::printf("%s: steepest slope %.3f free, %.3f limited to 0.2; volume change %.2e\n",
                sim::toString(boundary).c_str(), steepest(free), steepest(limited), limited.stats(dt).volume - before);
  }
}

// Substeps for the grid damping: enough that kappa dt is within 0.9 of its
// bound, and one fewer would not be.
TEST(SimParams, SubstepsKeepTheGridDampingWithinItsBound) {
  sim::WaterParams p{.n = 128, .extent = 4.0, .waveSpeed = 0.6, .damping = 0.3};
  for (const double kappa : {0.0, 5.0, 50.0, 500.0}) {
    p.gridDamping = kappa;
    const double frame = 1.0 / 30.0;
    const uint32_t k = sim::substepsFor(p, frame, 0.9);
    EXPECT_LE(kappa * frame / k, 0.9 * sim::gridDampingBound(p, frame / k)) << kappa;
    if (k > 2) {  // two keep lambda within its bound on this grid
      EXPECT_GT(kappa * frame / (k - 1), 0.9 * sim::gridDampingBound(p, frame / (k - 1))) << kappa;
    }
  }
  p.gridDamping = 2.0;
  EXPECT_EQ(sim::substepsFor(p, 1.0 / 30.0), 2u);  // the default scene: no more substeps than without it
}

TEST(SimParams, ImpossibleParametersAreRefused) {
  auto refused = [](sim::WaterParams p) { EXPECT_THROW(sim::validate(p), std::runtime_error); };
  refused({.n = 0});
  refused({.n = 1});
  refused({.extent = 0.0});
  refused({.extent = std::nan("")});
  refused({.waveSpeed = -1.0});
  refused({.damping = -0.1});
  refused({.maxSlope = std::numeric_limits<double>::infinity()});
  refused({.gridDamping = -1.0});
  refused({.gridDamping = std::nan("")});
  EXPECT_NO_THROW(sim::validate(sim::WaterParams{}));
}

}  // namespace tp::test
