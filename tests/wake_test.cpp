// A sphere crossing the pool (sim/wake_run.hpp) on lavapipe under
// validation: the wake it leaves is smooth, converges as the grid is refined,
// keeps the water's volume, and a sphere fully under the surface still moves
// it. The figures the tests see are printed; docs/water-numerics.md has them.
#include <gtest/gtest.h>

#include <cstdio>

#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/wake_run.hpp"

namespace tp::test {
namespace {

void print(const sim::WakeCase& c, const sim::WakeResult& r) {
  std::printf("grid %4u  %.1f c  %-9s  high %.4f  slope %6.3f  crest %.4f  trough %.4f  volume change %.2e of %.3f\n",
              c.grid, c.speedFraction, c.submerged ? "submerged" : "half in", r.measures.highShare, r.measures.maxSlope,
              r.measures.crest, r.measures.trough, r.volumeChange, r.submergedVolume);
}

}  // namespace

using Wake = GpuTest;

// Under 2% of the height variance above half the Nyquist wavenumber at every
// speed and immersion, on grids of 64 and 128 cells (the old centre-sampled
// forcing left 26-41% there). The slope stays under 1 at 0.2 c and, half
// in, at 0.5 c; the crest under 0.1 m at 0.2 c. Faster, the crest and the
// slope at the waterline are the depth-averaged model's answer to a sphere
// of 0.45 m in a pool of 1.2 m, which grows as the speed nears the wave
// speed (docs/water-numerics.md): only the smoothness is asserted there.
TEST_F(Wake, SmoothAtEverySpeedAndImmersion) {
  for (const uint32_t grid : {64u, 128u}) {
    for (const double speed : {0.2, 0.5, 0.9}) {
      for (const bool submerged : {false, true}) {
        const sim::WakeCase c{.grid = grid, .speedFraction = speed, .submerged = submerged};
        const sim::WakeResult r = sim::runWake(ctx(), c);
        print(c, r);
        SCOPED_TRACE(std::to_string(grid) + " cells, " + std::to_string(speed) + " c" +
                     (submerged ? ", submerged" : ", half in"));
        EXPECT_LT(r.measures.highShare, 0.02);
        if (speed == 0.2 || (speed == 0.5 && !submerged)) {
          EXPECT_LT(r.measures.maxSlope, 1.0);
        }
        if (speed == 0.2) {
          EXPECT_LT(r.measures.crest, 0.1);
        }
      }
    }
  }
}

// The same crossing on 128, 256 and 512 cells: the difference between
// successive grids falls (measured: by 1.45 with the default kappa 2; the
// chord's vertical edge at the waterline keeps the order low, about a half),
// and the water's volume is kept to round-off.
TEST_F(Wake, ConvergesAsTheGridIsRefinedAndKeepsTheVolume) {
  std::vector<sim::WakeResult> results;
  for (const uint32_t grid : {128u, 256u, 512u}) {
    const sim::WakeCase c{.grid = grid, .speedFraction = 0.5, .crossing = 1.4};
    results.push_back(sim::runWake(ctx(), c));
    print(c, results.back());
    EXPECT_LT(std::abs(results.back().volumeChange), 1e-5 * results.back().submergedVolume);
  }
  const double coarse = sim::rmsDifference(results[0].state, results[1].state);
  const double fine = sim::rmsDifference(results[1].state, results[2].state);
  std::printf("rms difference 128-256: %.3e m, 256-512: %.3e m, ratio %.2f\n", coarse, fine, coarse / fine);
  EXPECT_LT(fine, 0.8 * coarse);
}

// A sphere resting half in the water leaves still water still, to the bit.
TEST_F(Wake, RestingSphereLeavesStillWaterStill) {
  const sim::WaterParams p{.n = 128, .extent = 4.0, .waveSpeed = 0.6, .damping = 0.3, .gridDamping = 2.0};
  sim::GpuStepper stepper(ctx(), p, sim::flatState(p.n), sim::StepKernel::ActiveTiles);
  const glm::vec3 centre(1.7f, 0.0f, 2.3f);
  gpu::submitAndWait(
      ctx(),
      [&](const vk::raii::CommandBuffer& cmd) {
        for (int s = 0; s < 100; ++s) {
          stepper.recordSphereMove(cmd, centre, centre, 0.45f, 0.0f);
          stepper.recordSteps(cmd, 1, 1.0 / 60.0);
        }
      },
      "resting sphere");
  const sim::WaterState state = stepper.download();
  for (size_t k = 0; k < state.u.size(); ++k) {
    ASSERT_EQ(state.u[k], 0.0f) << "cell " << k;
    ASSERT_EQ(state.v[k], 0.0f) << "cell " << k;
  }
}

// WebGL Water's oldest open issue: there, a sphere wholly under the surface
// moving sideways leaves the water flat. Here its wake has a crest and a
// trough of centimetres, as smooth as the half-in sphere's.
TEST_F(Wake, SubmergedSphereMovingSidewaysMovesTheWater) {
  const sim::WakeCase c{.grid = 128, .speedFraction = 0.3, .submerged = true, .crossing = 1.4};
  const sim::WakeResult r = sim::runWake(ctx(), c);
  print(c, r);
  EXPECT_GT(r.measures.crest, 0.01);
  EXPECT_GT(r.measures.trough, 0.005);
  EXPECT_LT(r.measures.highShare, 0.02);
}

}  // namespace tp::test
