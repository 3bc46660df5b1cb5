#include "bench/bench_tiles.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "bench/time_steps.hpp"
#include "cli/gpu_session.hpp"
#include "gpu/timer.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::app {
namespace {

constexpr float kLevel = 1.0f;       // rest level of the water, as in a scene
constexpr float kAmplitude = 0.05f;  // drop height, relative to the 1 m grid
constexpr double kLambda = 0.5;      // Courant number

sim::WaterParams paramsFor(unsigned n) { return sim::WaterParams{.n = n, .extent = 1.0, .waveSpeed = 1.0}; }

struct Sample {
  double msPerStep = 0.0;
  double activeFraction = 1.0;  // tiles dispatched / (steps * all tiles)
};

// One submission of `steps` steps right after a drop of `radius` (as a
// fraction of the side; 0: none) on calm water, as the stepper's current
// dispatch mode runs it.
Sample timeOnce(const gpu::Context& ctx, gpu::GpuTimer& timer, sim::GpuStepper& stepper, double radius,
                uint32_t steps) {
  const auto p = stepper.params();
  const double dt = kLambda * p.h() / p.waveSpeed;
  stepper.reset(sim::flatState(p.n, kLevel));
  stepper.step(1, dt);  // a reset marks every tile: settle that outside the timing
  if (radius > 0.0) stepper.drop({float(0.5 * p.extent), float(0.5 * p.extent)}, float(radius * p.extent), kAmplitude);
  stepper.readTilesDispatched();
  Sample sample{.msPerStep = 1e3 * timeSteps(ctx, timer, stepper, steps, dt) / steps};
  if (stepper.kernel() == sim::StepKernel::ActiveTiles) {
    sample.activeFraction = double(stepper.readTilesDispatched().total()) / (double(steps) * stepper.tiles().count());
  }
  return sample;
}

struct Row {
  unsigned n = 0;
  double radius = 0.0;
  double activeFraction = 0.0;
  double msFull = 0.0, msActive = 0.0, msPlain = 0.0;
  double activeOverFull = 0.0;  // median of the ratios of the same repeat
  bool ruleActive = false;
};

// The three ways to step one case, interleaved repeat by repeat so that the
// ratios compare runs under the same load (the machine may be shared).
Row measure(const gpu::Context& ctx, sim::GpuStepper& tiles, sim::GpuStepper& plain, double radius,
            const BenchTilesOptions& o) {
  gpu::GpuTimer timer(ctx, 1);
  std::vector<double> full, active, onePerDispatch, ratios, fractions;
  for (uint32_t r = 0; r < o.repeats; ++r) {
    tiles.setTileDispatch(sim::TileDispatch::Full);
    full.push_back(timeOnce(ctx, timer, tiles, radius, o.steps).msPerStep);
    tiles.setTileDispatch(sim::TileDispatch::Active);
    const Sample a = timeOnce(ctx, timer, tiles, radius, o.steps);
    active.push_back(a.msPerStep);
    fractions.push_back(a.activeFraction);
    onePerDispatch.push_back(timeOnce(ctx, timer, plain, radius, o.steps).msPerStep);
    ratios.push_back(active.back() / full.back());
  }
  Row row{.n = tiles.params().n,
          .radius = radius,
          .activeFraction = median(fractions),
          .msFull = median(full),
          .msActive = median(active),
          .msPlain = median(onePerDispatch),
          .activeOverFull = median(ratios)};
  const uint32_t all = tiles.tiles().count();
  row.ruleActive = sim::preferActiveList(uint32_t(std::lround(row.activeFraction * all)), all);
  return row;
}

// The active fraction at which active and full take the same time, linear
// between the measured points around the first crossing (none: nullopt).
std::optional<double> crossover(const std::vector<Row>& rows, unsigned n) {
  const Row* previous = nullptr;
  for (const Row& r : rows) {
    if (r.n != n) continue;
    if (previous && previous->activeOverFull <= 1.0 && r.activeOverFull > 1.0) {
      const double d0 = previous->activeOverFull - 1.0, d1 = r.activeOverFull - 1.0;
      const double f0 = previous->activeFraction, f1 = r.activeFraction;
      return f0 + (f1 - f0) * (-d0) / (d1 - d0);
    }
    previous = &r;
  }
  return std::nullopt;
}

}  // namespace

int runBenchTiles(const BenchTilesOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  std::vector<Row> rows;
  for (unsigned n : o.sizes) {
    sim::GpuStepper tiles(ctx, paramsFor(n), sim::flatState(n, kLevel), sim::StepKernel::ActiveTiles);
    sim::GpuStepper plain(ctx, paramsFor(n), sim::flatState(n, kLevel), sim::StepKernel::OnePerDispatch);
    for (double radius : o.radii) {
      rows.push_back(measure(ctx, tiles, plain, radius, o));
      std::fprintf(stderr, "bench tiles: grid %u, drop radius %.3g measured\n", n, radius);
    }
  }

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "grid,drop_radius,active_fraction,ms_full,ms_active,ms_one_per_dispatch,active_over_full,rule,device\n";
  std::printf("%6s %8s %8s %10s %10s %10s %8s %7s\n", "grid", "radius", "active", "full ms", "active ms", "plain ms",
              "act/full", "rule");
  for (const Row& r : rows) {
    const char* rule = r.ruleActive ? "active" : "full";
    std::printf("%6u %8.3g %8.3f %10.4f %10.4f %10.4f %8.3f %7s\n", r.n, r.radius, r.activeFraction, r.msFull,
                r.msActive, r.msPlain, r.activeOverFull, rule);
    csv << r.n << "," << formatNumber("%.4g", r.radius) << "," << formatNumber("%.4g", r.activeFraction) << ","
        << formatNumber("%.6g", r.msFull) << "," << formatNumber("%.6g", r.msActive) << ","
        << formatNumber("%.6g", r.msPlain) << "," << formatNumber("%.4g", r.activeOverFull) << "," << rule << ",\""
        << ctx.deviceName() << "\"\n";
  }
  for (unsigned n : o.sizes) {
    const auto f = crossover(rows, n);
    if (f) {
      std::printf("grid %u: active and full cross at an active fraction of %.3f\n", n, *f);
    } else {
      std::printf("grid %u: no crossing of active and full in the measured range\n", n);
    }
  }
  commitBenchCsv(csvFile, csv, "plot_bench_tiles.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
