// The GPU water against independent answers: the double-precision CPU
// reference, the exact discrete solution of a clamp-boundary eigenmode, and
// the continuous mode (second-order convergence).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "gpu_test.hpp"
#include "sim/exact_mode.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/reference_sim.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

constexpr double kFloatEps = std::numeric_limits<float>::epsilon();

// Max |u_gpu - factor * u0| over the grid.
double modeError(const sim::WaterState& s, const sim::WaterState& initial, double factor) {
  double worst = 0.0;
  for (size_t k = 0; k < s.u.size(); ++k) worst = std::max(worst, std::abs(double(s.u[k]) - factor * initial.u[k]));
  return worst;
}

}  // namespace

using SimAccuracy = GpuTest;

// 1000 steps from white noise (every mode excited) around level 0, lambda = 0.5
// (0.3 with the slope limiter, within its bounds), some damping, with and
// without grid damping. Round-off in float32 grows at most linearly with the
// step count: the bound is steps * 4 * eps times the field's scale (max |u0|
// for u, (c / h) max |u0| for v, the velocity a height of that size drives),
// far below the O(1) relative error of a wrong stencil, boundary or limiter.
TEST_F(SimAccuracy, GpuMatchesCpuReferenceAfter1000Steps) {
  constexpr uint32_t kSteps = 1000;
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    for (double maxSlope : {0.0, 0.15}) {
      for (double gridDamping : {0.0, 8.0}) {
        sim::WaterParams p{.n = 50,
                           .extent = 1.0,
                           .waveSpeed = 1.0,
                           .damping = 0.3,
                           .boundary = boundary,
                           .maxSlope = maxSlope,
                           .gridDamping = gridDamping};
        const double dt = (maxSlope > 0.0 ? 0.3 : 0.5) * p.h() / p.waveSpeed;
        sim::checkStable(p, dt);
        const auto initial = randomState(p.n, 0.0, 0.02, 7);
        const double uScale = 0.01, vScale = p.waveSpeed / p.h() * uScale;
        sim::ReferenceSim reference(p, initial);
        reference.steps(kSteps, dt);
        for (auto kernel : {sim::StepKernel::OnePerDispatch, sim::StepKernel::Tiled}) {
          sim::GpuStepper gpu(ctx(), p, initial, kernel, 4);
          gpu.step(kSteps, dt);
          const auto s = gpu.download();
          SCOPED_TRACE("boundary " + sim::toString(boundary) + ", maxSlope " + std::to_string(maxSlope) +
                       ", grid damping " + std::to_string(gridDamping) + ", kernel " + std::to_string(int(kernel)));
          EXPECT_LT(maxAbsDifference(s.u, reference.u()), kSteps * 4 * kFloatEps * uScale);
          EXPECT_LT(maxAbsDifference(s.v, reference.v()), kSteps * 4 * kFloatEps * vScale);
        }
      }
    }
  }
}

// The slope limiter must actually bind in the case above, or the test would
// not test it: the limited run differs from the free one by far more than round-off.
TEST_F(SimAccuracy, SlopeLimiterIsActiveInTheComparedCase) {
  sim::WaterParams free{.n = 50, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.3};
  sim::WaterParams limited = free;
  limited.maxSlope = 0.15;
  const auto initial = randomState(50, 0.0, 0.02, 7);
  sim::ReferenceSim a(free, initial), b(limited, initial);
  a.steps(20, 0.3 * free.h());
  b.steps(20, 0.3 * free.h());
  double worst = 0.0;
  for (size_t k = 0; k < a.u().size(); ++k) worst = std::max(worst, std::abs(a.u()[k] - b.u()[k]));
  EXPECT_GT(worst, 1e-3);
}

// The one-step and the tiled multi-step kernels run the same arithmetic
// ("precise"), so they agree to the bit, for any halo and grid size.
TEST_F(SimAccuracy, TiledKernelIsBitIdenticalToOneStepPerDispatch) {
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    for (uint32_t n : {7u, 37u}) {
      sim::WaterParams p{.n = n,
                         .extent = 1.0,
                         .waveSpeed = 1.0,
                         .damping = 0.1,
                         .boundary = boundary,
                         .maxSlope = 0.15,
                         .gridDamping = 0.5};
      const auto initial = randomState(n, 0.5, 0.02, 11);
      const double dt = 0.45 * p.h();  // within the slope limiter's bound
      sim::checkStable(p, dt);
      sim::GpuStepper one(ctx(), p, initial, sim::StepKernel::OnePerDispatch);
      one.step(23, dt);
      const auto expected = one.download();
      for (uint32_t halo : {1u, 3u, 8u, sim::GpuStepper::kMaxHalo}) {
        sim::GpuStepper tiled(ctx(), p, initial, sim::StepKernel::Tiled, halo);
        tiled.step(23, dt);
        const auto got = tiled.download();
        EXPECT_EQ(got.u, expected.u) << "n " << n << " halo " << halo << " " << sim::toString(boundary);
        EXPECT_EQ(got.v, expected.v) << "n " << n << " halo " << halo << " " << sim::toString(boundary);
      }
    }
  }
}

// Over 10^4 steps the GPU follows the exact discrete solution to round-off, for
// both readings of "at rest": a stored v = 0 (DESIGN.md's cos((n + 1/2) theta) /
// cos(theta / 2)) and startAtRest() (cos(n theta)). The float32 error: the
// rounding of c^2 dt / h^2 to float shifts theta by at most eps relative, so the
// phase drifts by at most n theta eps, plus a random walk of per-step rounding,
// sqrt(n) 10 eps. The continuous mode differs from either by far more, so the
// test tells the exact discrete solution from a merely convergent one.
TEST_F(SimAccuracy, MatchesTheExactDiscreteModeOver10000Steps) {
  sim::WaterParams p{.n = 64, .extent = 1.0, .waveSpeed = 1.0};
  const sim::ExactMode mode{p, 3, 2, 1.0, 0.6 * p.h()};
  const double roundOffBound = (1e4 * mode.theta() + std::sqrt(1e4) * 10.0) * kFloatEps;
  for (bool stagger : {false, true}) {
    auto initial = sim::modeState(p.n, p.extent, 3, 2, 1.0);
    if (stagger) sim::startAtRest(initial, p, mode.dt);
    sim::GpuStepper gpu(ctx(), p, initial, sim::StepKernel::Tiled, 8);
    double worstDiscrete = 0.0, worstContinuous = 0.0;
    for (int chunk = 1; chunk <= 10; ++chunk) {
      gpu.step(1000, mode.dt);
      const auto s = gpu.download();
      const double n = 1000.0 * chunk;
      const double exact = stagger ? mode.discreteFactorAtRest(n) : mode.discreteFactorFromZeroVelocity(n);
      worstDiscrete = std::max(worstDiscrete, modeError(s, initial, exact));
      worstContinuous = std::max(worstContinuous, modeError(s, initial, mode.continuousFactor(n)));
    }
    EXPECT_LT(worstDiscrete, roundOffBound) << (stagger ? "startAtRest" : "stored v = 0");
    EXPECT_GT(worstContinuous, 10.0 * roundOffBound) << (stagger ? "startAtRest" : "stored v = 0");
  }
}

// The grid damping on the same mode, over 10^4 steps: the GPU follows the
// step's exact map of the mode (iterated in double) to round-off, and the
// long wave loses what kappa (h k)^2 / 2 predicts, a small fraction of it.
TEST_F(SimAccuracy, GridDampingMatchesTheExactDampedModeAndSparesLongWaves) {
  sim::WaterParams p{.n = 64, .extent = 1.0, .waveSpeed = 1.0, .gridDamping = 5.0};
  const sim::ExactMode mode{p, 3, 2, 1.0, 0.6 * p.h()};
  sim::checkStable(p, mode.dt);
  sim::WaterParams undamped = p;
  undamped.gridDamping = 0.0;
  const sim::ExactMode free{undamped, 3, 2, 1.0, mode.dt};
  EXPECT_NEAR(free.discreteFactorIterated(1000), free.discreteFactorAtRest(1000), 1e-9);  // the map is the scheme
  const double roundOffBound = (1e4 * mode.theta() + std::sqrt(1e4) * 10.0) * kFloatEps;
  auto initial = sim::modeState(p.n, p.extent, 3, 2, 1.0);
  sim::startAtRest(initial, p, mode.dt);
  sim::GpuStepper gpu(ctx(), p, initial, sim::StepKernel::Tiled, 8);
  gpu.step(10000, mode.dt);
  const double exact = mode.discreteFactorIterated(10000);
  EXPECT_LT(modeError(gpu.download(), initial, exact), roundOffBound);
  // After 1000 steps (9.4 s) the damped mode is the free one times
  // exp(-kappa sigma t / 2), sigma = 4 sin^2(M pi h / 2L) + 4 sin^2(N pi h / 2L), to
  // first order in kappa dt (sigma is 0.031 here, 8 for the checkerboard).
  const double t = 1000.0 * mode.dt, loss = std::exp(-0.5 * p.gridDamping * mode.sigma() * t);
  std::printf("mode (3, 2) on 64 cells after %.2f s with kappa 5: factor %.4f, free %.4f times %.4f = %.4f\n", t,
              mode.discreteFactorIterated(1000), free.discreteFactorAtRest(1000), loss,
              free.discreteFactorAtRest(1000) * loss);
  EXPECT_NEAR(mode.discreteFactorIterated(1000), free.discreteFactorAtRest(1000) * loss, 0.01);
}

// Error against the continuous mode at t = 0.75 s, lambda = 0.5, for grids 32..256.
std::vector<double> continuousErrors(gpu::Context& ctx, bool stagger, double gridDamping = 0.0) {
  std::vector<double> errors;
  for (uint32_t n : {32u, 64u, 128u, 256u}) {
    sim::WaterParams p{.n = n, .extent = 1.0, .waveSpeed = 1.0, .gridDamping = gridDamping};
    const double dt = 0.5 * p.h();
    const uint64_t steps = uint64_t(std::llround(0.75 / dt));
    const sim::ExactMode mode{p, 2, 1, 1.0, dt};
    const auto u0 = sim::modeState(n, p.extent, 2, 1, 1.0);
    auto initial = u0;
    if (stagger) sim::startAtRest(initial, p, dt);
    sim::GpuStepper gpu(ctx, p, initial, sim::StepKernel::Tiled, 8);
    gpu.step(steps, dt);
    errors.push_back(modeError(gpu.download(), u0, mode.continuousFactor(double(steps))));
  }
  return errors;
}

// Started at rest properly, the error falls by 4 per doubling of the grid:
// second order in h (and dt, lambda being fixed). The grid damping's loss,
// kappa (h k)^2 / 2, is second order too: with kappa 5 (the scenes' is 2)
// the rate stays.
TEST_F(SimAccuracy, ConvergesAtSecondOrderToTheContinuousMode) {
  for (double gridDamping : {0.0, 5.0}) {
    auto errors = continuousErrors(ctx(), true, gridDamping);
    for (size_t i = 1; i < errors.size(); ++i) {
      const double ratio = errors[i - 1] / errors[i];
      SCOPED_TRACE("grid damping " + std::to_string(gridDamping));
      std::printf("grid damping %.0f, grid %u: error %.3e, ratio %.2f\n", gridDamping, 32u << i, errors[i], ratio);
      EXPECT_GT(ratio, 3.6) << "grid " << (32u << i) << " errors " << errors[i - 1] << " -> " << errors[i];
      EXPECT_LT(ratio, 4.4) << "grid " << (32u << i) << " errors " << errors[i - 1] << " -> " << errors[i];
    }
  }
}

// Why startAtRest exists: a stored v = 0 starts half a step off, and the error
// then falls only by 2 per doubling (first order).
TEST_F(SimAccuracy, StoredZeroVelocityIsOnlyFirstOrder) {
  auto errors = continuousErrors(ctx(), false);
  for (size_t i = 1; i < errors.size(); ++i) {
    const double ratio = errors[i - 1] / errors[i];
    EXPECT_GT(ratio, 1.8) << "grid " << (32u << i);
    EXPECT_LT(ratio, 2.2) << "grid " << (32u << i);
  }
}

}  // namespace tp::test
