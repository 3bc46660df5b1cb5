// Solid cells in the water (WaterParams::solid): the boxes that stand through
// its surface. Checked against the exact discrete modes of the basins a wall
// of solid cells makes, against the double-precision reference, and against
// the scheme's own conserved volume and energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "gpu_test.hpp"
#include "scene/scene.hpp"
#include "sim/exact_mode.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/reference_sim.hpp"
#include "sim/water_scene.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

constexpr double kFloatEps = std::numeric_limits<float>::epsilon();

struct Kernel {
  sim::StepKernel kernel;
  uint32_t halo;
  const char* name;
};
constexpr Kernel kKernels[] = {{sim::StepKernel::OnePerDispatch, 1, "one step a dispatch"},
                               {sim::StepKernel::Tiled, 1, "tiled, halo 1"},
                               {sim::StepKernel::Tiled, 3, "tiled, halo 3"},
                               {sim::StepKernel::Tiled, 8, "tiled, halo 8"},
                               {sim::StepKernel::ActiveTiles, 1, "active tiles"}};

// Cell (i, j) of an n-grid, or its transpose: the same walls turned a quarter.
size_t cellAt(uint32_t n, uint32_t along, uint32_t across, bool transposed) {
  return transposed ? size_t(along) * n + across : size_t(across) * n + along;
}

// The cells of a 50-cell pool of 1 m under a box turned 30 degrees.
std::vector<uint32_t> turnedBoxMask() {
  scene::Scene scene;
  scene.water.grid = 50;
  scene.water.extent = 1.0f;
  scene.water.level = 0.0f;
  scene.boxes = {scene::Box{.center = {0.1f, 0.0f, -0.05f}, .size = {0.4f, 1.0f, 0.15f}, .yawDegrees = 30.0f}};
  return sim::solidCellsOf(scene);
}

}  // namespace

using SimSolid = GpuTest;

// A wall of solid cells from one side of the pool to the other splits it into
// two basins, each a pool of its own: a mode of the left basin (32 cells
// wide, its first mode) and one of the right (12 cells, its second) follow
// their exact discrete solutions (sim::ExactMode, as a 32- and a 12-cell pool
// of the same spacing) to round-off over 2000 steps: the wall's cells,
// started 0.9 m high, let no water through. Both ways round (the wall
// across x, then across z), with every kernel.
TEST_F(SimSolid, AWallOfSolidCellsMakesTwoPoolsWithTheirExactModes) {
  constexpr uint32_t n = 48, wallFrom = 32, wallTo = 36, steps = 2000;
  sim::WaterParams p{.n = n, .extent = 1.0, .waveSpeed = 1.0};
  const double h = p.h(), dt = 0.6 * h;
  const auto basin = [&](uint32_t cells) {
    sim::WaterParams b = p;
    b.n = cells;
    b.extent = cells * h;
    return b;
  };
  for (bool transposed : {false, true}) {
    const int m = transposed ? 0 : 1, nz = transposed ? 1 : 0;
    const sim::ExactMode left{basin(wallFrom), m, nz, 1.0, dt}, right{basin(n - wallTo), 2 * m, 2 * nz, 0.4, dt};
    sim::WaterParams walled = p;
    walled.solid.assign(sim::solidWords(n), 0u);
    sim::WaterState initial = sim::flatState(n);
    for (uint32_t across = 0; across < n; ++across) {
      for (uint32_t along = 0; along < n; ++along) {
        const size_t k = cellAt(n, along, across, transposed);
        if (along < wallFrom) {
          initial.u[k] += float(left.amplitude * std::cos(std::numbers::pi * (along + 0.5) / wallFrom));
        } else if (along < wallTo) {
          sim::markSolid(walled.solid, k);
          initial.u[k] = 0.9f;  // no water: it must not leak out
        } else {
          initial.u[k] +=
              float(right.amplitude * std::cos(2.0 * std::numbers::pi * (along - wallTo + 0.5) / (n - wallTo)));
        }
      }
    }
    const double leftFactor = left.discreteFactorFromZeroVelocity(steps);
    const double rightFactor = right.discreteFactorFromZeroVelocity(steps);
    const double bound = (steps * left.theta() + std::sqrt(double(steps)) * 10.0) * kFloatEps;
    for (const Kernel& k : kKernels) {
      sim::GpuStepper gpu(ctx(), walled, initial, k.kernel, k.halo);
      gpu.step(steps, dt);
      const auto s = gpu.download();
      double worst = 0.0;
      for (size_t c = 0; c < s.u.size(); ++c) {
        const uint32_t along = transposed ? uint32_t(c / n) : uint32_t(c % n);
        if (along >= wallFrom && along < wallTo) continue;  // no water: ghosts
        const double factor = along < wallFrom ? leftFactor : rightFactor;
        worst = std::max(worst, std::abs(double(s.u[c]) - factor * initial.u[c]));
      }
      SCOPED_TRACE(std::string(k.name) + (transposed ? ", the wall across z" : ", the wall across x"));
      std::printf("%s, %s: worst error %.3g m against the exact modes (bound %.3g)\n", k.name,
                  transposed ? "across z" : "across x", worst, bound);
      EXPECT_LT(worst, bound);
    }
    // The walls matter: without them the two modes run into each other.
    sim::GpuStepper open(ctx(), p, initial, sim::StepKernel::OnePerDispatch);
    open.step(steps, dt);
    const auto s = open.download();
    double worst = 0.0;
    for (size_t c = 0; c < s.u.size(); ++c) {
      const uint32_t along = transposed ? uint32_t(c / n) : uint32_t(c % n);
      if (along < wallFrom) worst = std::max(worst, std::abs(s.u[c] - leftFactor * initial.u[c]));
    }
    EXPECT_GT(worst, 100.0 * bound);
  }
}

// Around a turned box (the cells under it solid, as solidCellsOf makes them)
// the GPU steps what the double-precision reference steps, the solid cells'
// ghost heights included, to the round-off bound of
// GpuMatchesCpuReferenceAfter1000Steps, with damping, grid damping and the
// slope limiter on, every kernel to the same bits.
TEST_F(SimSolid, GpuMatchesTheReferenceAroundATurnedBox) {
  constexpr uint32_t kSteps = 1000;
  sim::WaterParams p{.n = 50,
                     .extent = 1.0,
                     .waveSpeed = 1.0,
                     .damping = 0.3,
                     .maxSlope = 0.15,
                     .gridDamping = 8.0,
                     .solid = turnedBoxMask()};
  const double dt = 0.3 * p.h() / p.waveSpeed;
  sim::checkStable(p, dt);
  const auto initial = randomState(p.n, 0.0, 0.02, 7);
  const double uScale = 0.01, vScale = p.waveSpeed / p.h() * uScale;
  sim::ReferenceSim reference(p, initial);
  reference.steps(kSteps, dt);
  sim::WaterState first;
  for (const Kernel& k : kKernels) {
    sim::GpuStepper gpu(ctx(), p, initial, k.kernel, k.halo);
    gpu.step(kSteps, dt);
    const auto s = gpu.download();
    SCOPED_TRACE(k.name);
    EXPECT_LT(maxAbsDifference(s.u, reference.u()), kSteps * 4 * kFloatEps * uScale);
    EXPECT_LT(maxAbsDifference(s.v, reference.v()), kSteps * 4 * kFloatEps * vScale);
    if (first.n == 0) first = s;
    EXPECT_EQ(s.u, first.u);  // the kernels share their arithmetic: the same bits
    EXPECT_EQ(s.v, first.v);
  }
}

// A mask that comes through setParams acts as one given at the start, and
// one taken away leaves open water: after 300 steps over the turned box with
// every kernel, the same bits as a stepper made with the mask (or without
// it) from the start. The mask changes the water (measured: by 6.9e-4 m,
// the bound 1e-5 m), so the test can fail.
TEST_F(SimSolid, AMaskSetLaterActsAsOneGivenAtTheStart) {
  constexpr uint32_t kSteps = 300;
  sim::WaterParams open{.n = 50, .extent = 1.0, .waveSpeed = 1.0, .damping = 0.3, .gridDamping = 8.0};
  sim::WaterParams walled = open;
  walled.solid = turnedBoxMask();
  const double dt = 0.3 * open.h() / open.waveSpeed;
  const auto initial = randomState(open.n, 0.0, 0.02, 11);
  for (const Kernel& k : kKernels) {
    SCOPED_TRACE(k.name);
    const auto run = [&](const sim::WaterParams& made, const sim::WaterParams* later) {
      sim::GpuStepper gpu(ctx(), made, initial, k.kernel, k.halo);
      if (later != nullptr) gpu.setParams(*later);
      gpu.step(kSteps, dt);
      return gpu.download();
    };
    const sim::WaterState withMask = run(walled, nullptr), maskSetLater = run(open, &walled);
    const sim::WaterState without = run(open, nullptr), maskTakenAway = run(walled, &open);
    EXPECT_EQ(maskSetLater.u, withMask.u);
    EXPECT_EQ(maskSetLater.v, withMask.v);
    EXPECT_EQ(maskTakenAway.u, without.u);
    EXPECT_EQ(maskTakenAway.v, without.v);
    EXPECT_GT(maxAbsDifference(withMask.u, std::vector<double>(without.u.begin(), without.u.end())), 1e-5);
  }
}

// Drops falling beside a box that stands through the surface: with no
// damping the water's volume and the scheme's energy (water_stats.comp, the
// solid cells' edges left out as the step leaves them) stay what they were
// over 4000 steps while the waves strike the box, and the reference's
// statistics of its own run agree.
TEST_F(SimSolid, VolumeAndEnergyAreKeptAsWavesStrikeABox) {
  constexpr int kChunks = 4, kChunk = 1000;
  scene::Scene scene;
  scene.water.grid = 64;
  scene.water.extent = 2.0f;
  scene.water.level = 0.0f;
  scene.boxes = {scene::Box{.center = {0.2f, -0.3f, 0.1f}, .size = {0.5f, 0.8f, 0.3f}, .yawDegrees = -20.0f}};
  sim::WaterParams p{.n = 64, .extent = 2.0, .waveSpeed = 1.0, .solid = sim::solidCellsOf(scene)};
  const double dt = 0.5 * p.h();
  auto initial = sim::flatState(p.n, 1.0f);
  sim::addDrop(initial, p.extent, 0.6, 1.0, 0.15, 0.05);
  sim::addDrop(initial, p.extent, 1.5, 1.4, 0.1, 0.03);
  sim::GpuStepper gpu(ctx(), p, initial, sim::StepKernel::ActiveTiles);
  sim::ReferenceSim reference(p, initial);
  const auto waterVolume = [&](const sim::WaterState& w) {
    double sum = 0.0;
    for (size_t c = 0; c < w.u.size(); ++c) sum += sim::isSolid(p.solid, c) ? 0.0 : double(w.u[c]);
    return sum * p.h() * p.h();
  };
  const double volume = waterVolume(initial), energy = gpu.stats(dt).energy;
  double worstVolume = 0.0, worstEnergy = 0.0;
  for (int chunk = 0; chunk < kChunks; ++chunk) {
    gpu.step(kChunk, dt);
    reference.steps(kChunk, dt);
    worstVolume = std::max(worstVolume, std::abs(waterVolume(gpu.download()) - volume));
    EXPECT_NEAR(gpu.stats(dt).volume, waterVolume(gpu.download()), 1e-6 * volume);
    const double now = gpu.stats(dt).energy;
    worstEnergy = std::max(worstEnergy, std::abs(now - energy) / energy);
    EXPECT_NEAR(now, reference.stats(dt).energy, 1e-4 * energy);
  }
  // Heights near the rest level of 1 differ exactly in float, so the step
  // keeps the volume but for the rounding of each new height, at most half
  // an ulp of 1: a random walk of sqrt(steps x cells) of them, bounded at
  // three deviations. The drops hold 1.3e-3 m^3; water lost into the box
  // or gained from it each step would pass the bound within a few steps.
  const double roundOff = 3.0 * std::sqrt(double(kChunks * kChunk) * p.n * p.n) * 0.5 * kFloatEps * p.h() * p.h();
  std::printf("4000 steps against a box: volume off by %.3g m^3 (bound %.3g), energy by %.3g of itself\n", worstVolume,
              roundOff, worstEnergy);
  EXPECT_LT(worstVolume, roundOff);
  EXPECT_LT(worstEnergy, 1e-4);
}

// Which cells solidCellsOf marks: those whose centres lie in the footprint of
// a box that stands through the rest level, turned by its yaw; none for a box
// wholly under or over the level. The marked area is the footprint's to
// within the cells its outline crosses.
TEST(SolidCells, BoxesThroughTheLevelMarkTheCellsUnderThem) {
  scene::Scene scene;
  scene.water.grid = 128;
  scene.water.extent = 4.0f;
  scene.water.level = -0.15f;
  const scene::Box through{.center = {0.5f, -0.3f, -0.4f}, .size = {0.9f, 0.7f, 0.35f}, .yawDegrees = 35.0f};
  for (const float y : {-1.0f, 0.5f}) {  // wholly under, wholly over
    scene.boxes = {through};
    scene.boxes[0].center.y = y;
    EXPECT_TRUE(sim::solidCellsOf(scene).empty()) << "box at height " << y;
  }
  scene.boxes = {through};
  const auto solid = sim::solidCellsOf(scene);
  ASSERT_EQ(solid.size(), sim::solidWords(128));
  const double h = 4.0 / 128;
  size_t marked = 0;
  for (size_t k = 0; k < size_t(128) * 128; ++k) marked += sim::isSolid(solid, k);
  const double area = 0.9 * 0.35, outline = 2.0 * (0.9 + 0.35);
  std::printf("footprint %.4f m^2, marked %.4f m^2\n", area, marked * h * h);
  EXPECT_NEAR(marked * h * h, area, outline * h);
  // The yaw turns from +x towards -z: the box's far end along its own x lies
  // at centre + 0.4 (cos 35, -sin 35); the same point mirrored in z does not.
  const auto cellOf = [&](double x, double z) { return size_t((z + 2.0) / h) * 128 + size_t((x + 2.0) / h); };
  const double c = std::cos(glm::radians(35.0)), s = std::sin(glm::radians(35.0));
  EXPECT_TRUE(sim::isSolid(solid, cellOf(0.5 + 0.4 * c, -0.4 - 0.4 * s)));
  EXPECT_FALSE(sim::isSolid(solid, cellOf(0.5 + 0.4 * c, -0.4 + 0.4 * s)));
}

// A mask that does not fit the grid is refused with one clear line.
TEST(SolidCells, AMaskOfAnotherGridIsRefused) {
  sim::WaterParams p{.n = 64};
  p.solid.assign(sim::solidWords(32), 0u);
  try {
    sim::validate(p);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("solid-cell mask"), std::string::npos) << e.what();
  }
}

}  // namespace tp::test
