// The benchmark's C++ peer computes the same step as the reference.
#include <gtest/gtest.h>

#include <limits>

#include "sim/cpu_stepper.hpp"
#include "sim/reference_sim.hpp"
#include "sim_support.hpp"

namespace tp::test {

TEST(CpuStepper, MatchesTheReference) {
  constexpr uint64_t kSteps = 300;
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    for (double maxSlope : {0.0, 0.15}) {
      sim::WaterParams p{
          .n = 37, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.2, .boundary = boundary, .maxSlope = maxSlope};
      const double dt = 0.55 * p.h();
      const auto initial = randomState(p.n, 0.0, 0.02, 13);
      sim::ReferenceSim reference(p, initial);
      reference.steps(kSteps, dt);
      sim::CpuStepper cpu(p, initial);
      cpu.steps(kSteps, dt);
      // The same round-off bound as the GPU's (sim_accuracy_test.cpp).
      const double eps = std::numeric_limits<float>::epsilon(), uScale = 0.01, vScale = uScale / p.h();
      EXPECT_LT(maxAbsDifference(cpu.state().u, reference.u()), kSteps * 4 * eps * uScale) << sim::toString(boundary);
      EXPECT_LT(maxAbsDifference(cpu.state().v, reference.v()), kSteps * 4 * eps * vScale) << sim::toString(boundary);
    }
  }
}

}  // namespace tp::test
