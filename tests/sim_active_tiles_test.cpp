// Active-tile stepping against an independent answer: the plain full-grid
// kernel (one step per dispatch over every cell), compared bit for bit, and the
// number of tiles dispatched against the reach of the waves (one cell per step).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>

#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

using Script = std::function<void(sim::GpuStepper&)>;

constexpr uint32_t kTile = TP_WATER_TILE;
constexpr float kLevel = 1.0f;  // a rest level far above the waves, as in a scene

double dtOf(const sim::WaterParams& p) { return 0.5 * p.h() / p.waveSpeed; }

// Cells whose u or v differ in any bit.
size_t differingCells(const sim::WaterState& a, const sim::WaterState& b) {
  size_t count = 0;
  for (size_t k = 0; k < a.u.size(); ++k) {
    count += std::bit_cast<uint32_t>(a.u[k]) != std::bit_cast<uint32_t>(b.u[k]) ||
             std::bit_cast<uint32_t>(a.v[k]) != std::bit_cast<uint32_t>(b.v[k]);
  }
  return count;
}

// The state after `script`, run by a stepper with `kernel`.
sim::WaterState run(const gpu::Context& ctx, const sim::WaterParams& p, const sim::WaterState& initial,
                    sim::StepKernel kernel, const Script& script) {
  sim::GpuStepper stepper(ctx, p, initial, kernel);
  script(stepper);
  return stepper.download();
}

// Runs `script` on the plain full-grid kernel and on active tiles (in `mode`),
// and expects the same bits, and some motion, or the comparison proves nothing.
void expectSameAsFullGrid(const gpu::Context& ctx, const sim::WaterParams& p, const sim::WaterState& initial,
                          const Script& script, sim::TileDispatch mode = sim::TileDispatch::Active) {
  const auto plain = run(ctx, p, initial, sim::StepKernel::OnePerDispatch, script);
  const auto tiles = run(ctx, p, initial, sim::StepKernel::ActiveTiles, [&](sim::GpuStepper& s) {
    s.setTileDispatch(mode);
    script(s);
  });
  EXPECT_EQ(differingCells(plain, tiles), 0u) << "of " << plain.u.size() << " cells";
  EXPECT_GT(differingCells(plain, initial), plain.u.size() / 100) << "the script hardly moved the water";
}

// Tiles [lo, hi] per axis that hold cells within `reach` of the cell box [c0, c1], widened
// by one tile of halo and cut to the grid (clamp boundary).
uint64_t tilesWithinReach(int c0, int c1, int reach, uint32_t n) {
  const int perSide = int((n + kTile - 1) / kTile);
  const int lo = std::max(0, std::max(0, c0 - reach) / int(kTile) - 1);
  const int hi = std::min(perSide - 1, (c1 + reach) / int(kTile) + 1);
  return uint64_t(hi - lo + 1) * uint64_t(hi - lo + 1);
}

}  // namespace

using SimActiveTiles = GpuTest;

// Drops (one in the middle, one across the edge, which with wrap reaches the
// far side), and a sphere moving, between steps, on both boundaries, with and
// without the slope limit and damping: every combination gives the bits of
// the full-grid step.
TEST_F(SimActiveTiles, MatchesFullGridBitwiseWithDropsAndSpheres) {
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    for (double maxSlope : {0.0, 0.15}) {
      for (double damping : {0.0, 0.4}) {
        const sim::WaterParams p{
            .n = 256, .extent = 1.0, .waveSpeed = 1.0, .damping = damping, .boundary = boundary, .maxSlope = maxSlope};
        const double dt = dtOf(p);
        SCOPED_TRACE("boundary " + sim::toString(boundary) + ", maxSlope " + std::to_string(maxSlope) + ", damping " +
                     std::to_string(damping));
        expectSameAsFullGrid(ctx(), p, sim::flatState(p.n, kLevel), [&](sim::GpuStepper& s) {
          s.drop({0.4f, 0.55f}, 0.03f, 0.2f);
          s.step(40, dt);
          s.drop({0.005f, 0.8f}, 0.05f, -0.1f);
          s.step(40, dt);
          s.moveSphere({0.7f, 0.95f, 0.3f}, {0.72f, 0.93f, 0.3f}, 0.1f, kLevel, 0.0);
          s.step(40, dt);
        });
      }
    }
  }
}

// The renderer's pattern: drops and sphere moves recorded between steps in one
// command buffer, one step at a time.
TEST_F(SimActiveTiles, MatchesFullGridWithDisturbancesRecordedBetweenSteps) {
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    const sim::WaterParams p{.n = 256, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.2, .boundary = boundary};
    const double dt = dtOf(p);
    SCOPED_TRACE("boundary " + sim::toString(boundary));
    expectSameAsFullGrid(ctx(), p, sim::flatState(p.n, kLevel), [&](sim::GpuStepper& s) {
      gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
        s.recordDrop(cmd, {0.995f, 0.995f}, 0.04f, 0.1f);
        for (int k = 0; k < 60; ++k) {
          const float x = 0.2f + 0.004f * float(k);
          s.recordSphereMove(cmd, {x, 0.97f, 0.5f}, {x + 0.004f, 0.97f, 0.5f}, 0.06f, kLevel, dt);
          s.recordSteps(cmd, 1, dt);
          if (k == 30) s.recordDrop(cmd, {0.6f, 0.1f}, 0.02f, 0.05f);
        }
      });
    });
  }
}

// reset() to another state mid-run: both buffers and every tile start again.
TEST_F(SimActiveTiles, MatchesFullGridAcrossReset) {
  const sim::WaterParams p{.n = 256, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.1, .boundary = sim::Boundary::Wrap};
  const double dt = dtOf(p);
  auto restart = sim::flatState(p.n, kLevel);
  sim::addDrop(restart, p.extent, 0.8, 0.2, 0.05, 0.1);
  expectSameAsFullGrid(ctx(), p, randomState(p.n, kLevel, 0.01, 3), [&](sim::GpuStepper& s) {
    s.step(30, dt);
    s.drop({0.5f, 0.5f}, 0.05f, 0.1f);
    s.step(5, dt);
    s.reset(restart);
    s.step(50, dt);
    s.drop({0.1f, 0.1f}, 0.03f, 0.1f);
    s.step(20, dt);
  });
}

// Full and active dispatch alternate at step boundaries (and the automatic
// rule chooses in between): still the full grid's bits.
TEST_F(SimActiveTiles, SwitchingBetweenFullAndActiveStaysBitwise) {
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    const sim::WaterParams p{
        .n = 256, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.0, .boundary = boundary, .maxSlope = 0.15};
    const double dt = dtOf(p);
    SCOPED_TRACE("boundary " + sim::toString(boundary));
    expectSameAsFullGrid(ctx(), p, sim::flatState(p.n, kLevel), [&](sim::GpuStepper& s) {
      s.step(1, dt);  // past the reset's marking of every tile, so that the drops' own marks count
      s.drop({0.3f, 0.3f}, 0.04f, 0.2f);
      const sim::TileDispatch modes[] = {sim::TileDispatch::Active, sim::TileDispatch::Full, sim::TileDispatch::Auto};
      for (int k = 0; k < 12; ++k) {
        s.setTileDispatch(modes[k % 3]);
        s.step(1 + k % 5, dt);
        if (s.kernel() == sim::StepKernel::ActiveTiles && modes[k % 3] != sim::TileDispatch::Auto) {
          EXPECT_EQ(s.lastStepsFull(), modes[k % 3] == sim::TileDispatch::Full);
        }
        if (k == 5) s.drop({0.7f, 0.6f}, 0.03f, -0.1f);  // before an active step
      }
    });
  }
}

// A small drop on a 512^2 grid: step k after it can only have changed cells
// within k of the drop (the stencil reaches one cell per step), so it lists at
// most the tiles within reach plus one tile of halo; the first steps list a
// few tiles of the 1024, and the list grows as the waves spread.
TEST_F(SimActiveTiles, ListsOnlyTilesWithinReachOfTheDrop) {
  const sim::WaterParams p{.n = 512, .extent = 1.0, .waveSpeed = 1.0, .boundary = sim::Boundary::Clamp};
  const double dt = dtOf(p);
  sim::GpuStepper s(ctx(), p, sim::flatState(p.n, kLevel), sim::StepKernel::ActiveTiles);
  s.setTileDispatch(sim::TileDispatch::Active);
  s.step(1, dt);  // after a reset every tile counts as changed once
  EXPECT_EQ(s.readTilesDispatched().listed, s.tiles().count());

  const double cx = 0.45, cz = 0.45, radius = 4.5 * p.h();
  s.drop({float(cx), float(cz)}, float(radius), 0.1f);
  const int c0 = int(std::floor((cx - radius) / p.h())), c1 = int(std::ceil((cx + radius) / p.h()));
  std::vector<uint64_t> listed;
  for (int k = 0; k < 60; ++k) {
    s.step(1, dt);
    const auto counts = s.readTilesDispatched();
    EXPECT_EQ(counts.direct, 0u);
    EXPECT_LE(counts.listed, tilesWithinReach(c0, c1, k, p.n)) << "step " << k << " after the drop";
    EXPECT_GE(counts.listed, 1u) << "step " << k << " after the drop";
    listed.push_back(counts.listed);
  }
  EXPECT_LE(listed.front(), 16u);
  EXPECT_LT(listed.back(), s.tiles().count() / 4);
  EXPECT_GT(listed.back(), listed.front());
}

// Water at rest (at any level, v = 0) stays bitwise at rest: after the first
// step, no tile is dispatched at all; forced full, every tile is, every step.
TEST_F(SimActiveTiles, CalmWaterDispatchesNoTiles) {
  for (auto boundary : {sim::Boundary::Clamp, sim::Boundary::Wrap}) {
    const sim::WaterParams p{
        .n = 300, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.2, .boundary = boundary, .maxSlope = 0.1};
    sim::GpuStepper s(ctx(), p, sim::flatState(p.n, kLevel), sim::StepKernel::ActiveTiles);
    s.setTileDispatch(sim::TileDispatch::Active);
    s.step(1, dtOf(p));
    EXPECT_EQ(s.readTilesDispatched().total(), s.tiles().count());
    s.step(20, dtOf(p));
    EXPECT_EQ(s.readTilesDispatched().total(), 0u);
    s.setTileDispatch(sim::TileDispatch::Full);
    s.step(3, dtOf(p));
    const auto full = s.readTilesDispatched();
    EXPECT_EQ(full.direct, 3u * s.tiles().count());
    EXPECT_EQ(full.listed, 0u);
    EXPECT_EQ(differingCells(s.download(), sim::flatState(p.n, kLevel)), 0u);
  }
}

// The automatic choice follows the count of the last submission: full after
// a reset (every tile counts as changed) and while waves cover the grid,
// the list once the water is calm or the disturbance is small. At 0% and 100%
// active, any rule between the two measured extremes gives these answers.
TEST_F(SimActiveTiles, AutomaticDispatchFollowsTheLastCount) {
  const sim::WaterParams p{.n = 256, .extent = 1.0, .waveSpeed = 1.0, .boundary = sim::Boundary::Wrap};
  const double dt = dtOf(p);
  sim::GpuStepper s(ctx(), p, sim::flatState(p.n, kLevel), sim::StepKernel::ActiveTiles);
  s.step(1, dt);
  EXPECT_TRUE(s.lastStepsFull()) << "after a reset";
  s.step(1, dt);
  EXPECT_FALSE(s.lastStepsFull()) << "calm water";
  s.drop({0.5f, 0.5f}, 0.02f, 0.1f);
  s.step(3, dt);
  EXPECT_FALSE(s.lastStepsFull()) << "a small drop";
  s.reset(randomState(p.n, kLevel, 0.01, 5));
  s.step(1, dt);
  s.step(1, dt);
  EXPECT_TRUE(s.lastStepsFull()) << "waves everywhere";
  const auto counts = s.readTilesDispatched();
  EXPECT_EQ(counts.direct, 3u * s.tiles().count()) << "the three full steps";
  EXPECT_GT(counts.listed, 0u);
  EXPECT_LE(counts.listed, 3u * 4 * 4) << "the drop touches 2x2 tiles: with their halo, 4x4 per step";
}

}  // namespace tp::test
