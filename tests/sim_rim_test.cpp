// The rim (docs/water-numerics.md, "The rim"): along the walls of the clamp
// boundary, water over the rim spills out of the pool. Every kernel against
// the double-precision reference, which implements the rule apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "gpu_test.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/reference_sim.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

constexpr double kFloatEps = std::numeric_limits<float>::epsilon();
constexpr uint64_t kSteps = 200;

// A drop against the west wall, two and a half times as high as the rim.
sim::WaterState dropAtTheWall(const sim::WaterParams& p) {
  sim::WaterState s = sim::flatState(p.n);
  sim::addDrop(s, p.extent, 0.05, 0.5, 0.15, 0.05);
  return s;
}

sim::WaterParams rimParams() {
  return sim::WaterParams{
      .n = 64, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.3, .gridDamping = 2.0, .spillHeight = 0.02};
}

}  // namespace

using SimRim = GpuTest;

// Every kernel follows the reference to round-off with the rim binding; the
// walls never stand above the rim; the water that spilled is gone from the
// volume; and without the rim the same run differs by far more than
// round-off (so the rule is what the comparison tests).
TEST_F(SimRim, WaterOverTheRimSpillsAlongTheWalls) {
  const sim::WaterParams p = rimParams();
  const double dt = 0.5 * p.h() / p.waveSpeed;
  const sim::WaterState initial = dropAtTheWall(p);
  sim::ReferenceSim reference(p, initial);
  reference.steps(kSteps, dt);
  sim::WaterParams noRim = p;
  noRim.spillHeight = std::numeric_limits<double>::infinity();
  sim::ReferenceSim free(noRim, initial);
  free.steps(kSteps, dt);
  double apart = 0.0;
  for (size_t k = 0; k < free.u().size(); ++k) apart = std::max(apart, std::abs(free.u()[k] - reference.u()[k]));
  EXPECT_GT(apart, 1e-3);
  const double uScale = 0.05, vScale = p.waveSpeed / p.h() * uScale;
  for (const auto kernel : {sim::StepKernel::OnePerDispatch, sim::StepKernel::Tiled, sim::StepKernel::ActiveTiles}) {
    SCOPED_TRACE("kernel " + std::to_string(int(kernel)));
    sim::GpuStepper gpu(ctx(), p, initial, kernel, 4);
    gpu.step(kSteps, dt);
    const sim::WaterState s = gpu.download();
    EXPECT_LT(maxAbsDifference(s.u, reference.u()), kSteps * 4 * kFloatEps * uScale);
    EXPECT_LT(maxAbsDifference(s.v, reference.v()), kSteps * 4 * kFloatEps * vScale);
    EXPECT_LE(highestAlongTheWalls(s.u, p.n), float(p.spillHeight));
    EXPECT_LT(volumeOf(s, p.h()), volumeOf(initial, p.h()) - 1e-5);  // some water left the pool
  }
}

// The kernels agree to the bit with the rim binding, as they do without it.
TEST_F(SimRim, KernelsAgreeToTheBitWhileSpilling) {
  const sim::WaterParams p = rimParams();
  const double dt = 0.5 * p.h() / p.waveSpeed;
  const sim::WaterState initial = dropAtTheWall(p);
  sim::GpuStepper one(ctx(), p, initial, sim::StepKernel::OnePerDispatch);
  one.step(37, dt);
  const sim::WaterState expected = one.download();
  for (const auto kernel : {sim::StepKernel::Tiled, sim::StepKernel::ActiveTiles}) {
    sim::GpuStepper other(ctx(), p, initial, kernel, 8);
    other.step(37, dt);
    const sim::WaterState got = other.download();
    EXPECT_EQ(got.u, expected.u) << "kernel " << int(kernel);
    EXPECT_EQ(got.v, expected.v) << "kernel " << int(kernel);
  }
}

}  // namespace tp::test
