// Drops and the moving sphere against closed forms and the CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/wake_measures.hpp"
#include "sim_support.hpp"

namespace tp::test {

using SimInteraction = GpuTest;

TEST_F(SimInteraction, DropMatchesCpuAndItsClosedFormVolume) {
  const sim::WaterParams p{.n = 128, .extent = 2.0};
  const double radius = 0.3, amplitude = 0.05;
  sim::GpuStepper gpu(ctx(), p, sim::flatState(p.n, 1.0f), sim::StepKernel::OnePerDispatch);
  gpu.drop({0.7f, 1.1f}, float(radius), float(amplitude));
  const auto got = gpu.download();
  auto expected = sim::flatState(p.n, 1.0f);
  sim::addDrop(expected, p.extent, 0.7, 1.1, radius, amplitude);
  double worst = 0.0;
  for (size_t k = 0; k < got.u.size(); ++k) worst = std::max(worst, double(std::abs(got.u[k] - expected.u[k])));
  EXPECT_LT(worst, 4.0 * std::numeric_limits<float>::epsilon());  // cos in float on the GPU, at heights near 1
  // amplitude (1 + cos(pi r / R)) / 2 integrates to amplitude R^2 (pi/2 - 2/pi).
  const double closedForm = amplitude * radius * radius * (glm::half_pi<double>() - 2.0 / glm::pi<double>());
  const double added = volumeOf(got, p.h()) - 1.0 * p.extent * p.extent;
  EXPECT_NEAR(added, closedForm, 0.01 * closedForm);
}

// A sphere lowered from above the water into it: the surface rises by the
// volume the sphere now occupies below the rest level, the spherical cap's
// (closed form; the columns' quadrature is within 1e-5 of it,
// sphere_column_test.cpp, and the GPU's float sums add a little).
TEST_F(SimInteraction, SphereRaisesTheSurfaceByItsSubmergedVolume) {
  const sim::WaterParams p{.n = 256, .extent = 2.0};
  const float level = 1.0f, radius = 0.25f;
  sim::GpuStepper gpu(ctx(), p, sim::flatState(p.n, level), sim::StepKernel::OnePerDispatch);
  const double v0 = volumeOf(gpu.download(), p.h());
  const glm::vec3 above(0.9f, 1.5f, 1.0f), half(0.9f, 1.0f, 1.0f), deep(0.9f, 0.6f, 1.0f);
  gpu.moveSphere(above, half, radius, level, 0.0);
  const double halfIn = volumeOf(gpu.download(), p.h()) - v0;
  EXPECT_NEAR(halfIn, sim::sphereCapVolume(radius, half.y, level), 1e-4 * sim::sphereCapVolume(radius, half.y, level));
  gpu.moveSphere(half, deep, radius, level, 0.0);
  const double fullyIn = volumeOf(gpu.download(), p.h()) - v0;
  EXPECT_NEAR(fullyIn, sim::sphereCapVolume(radius, deep.y, level), 1e-4 * sim::sphereCapVolume(radius, deep.y, level));
  // Back out: every column returns to the rest level (to float rounding).
  gpu.moveSphere(deep, above, radius, level, 0.0);
  const auto back = gpu.download();
  for (float u : back.u) ASSERT_NEAR(u, level, 4.0f * std::numeric_limits<float>::epsilon());
}

TEST_F(SimInteraction, DropsAndSphereAreSynchronisationClean) {
  // Interleaved steps, drops, sphere moves and statistics in one command
  // buffer: the stepper's barriers must satisfy synchronization validation.
  const sim::WaterParams p{.n = 64, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.2};
  sim::GpuStepper gpu(ctx(), p, sim::flatState(p.n, 0.5f), sim::StepKernel::Tiled, 4);
  const double dt = 0.5 * p.h();
  gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
    gpu.recordDrop(cmd, {0.5f, 0.5f}, 0.1f, 0.02f);
    gpu.recordSteps(cmd, 7, dt);
    gpu.recordSphereMove(cmd, {0.3f, 0.7f, 0.3f}, {0.35f, 0.5f, 0.3f}, 0.1f, 0.5f, dt);
    gpu.recordSteps(cmd, 3, dt);
    gpu.recordStats(cmd, dt);
  });
  EXPECT_EQ(gpu.readStats().nonFinite, 0u);
}

}  // namespace tp::test
