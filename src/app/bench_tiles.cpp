#include "app/bench_tiles.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "app/bench_output.hpp"
#include "app/gpu_session.hpp"
#include "app/plot.hpp"
#include "gpu/submit.hpp"
#include "gpu/timer.hpp"
#include "io/atomic_file.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::app {
namespace {

constexpr float kLevel = 1.0f;       // rest level of the water, as in a scene
constexpr float kAmplitude = 0.05f;  // drop height, relative to the 1 m grid
constexpr double kLambda = 0.5;      // Courant number

sim::WaterParams paramsFor(unsigned n) { return sim::WaterParams{.n = n, .extent = 1.0, .waveSpeed = 1.0}; }

struct Timed {
  double msPerStep = 0.0;
  double activeFraction = 0.0;  // tiles dispatched / (steps * all tiles)
};

// Median over `repeats` of one submission of `steps` steps right after a drop
// of `radius` (as a fraction of the side; 0: none) on calm water, as the stepper's
// current dispatch mode runs it.
Timed timeSteps(const gpu::Context& ctx, sim::GpuStepper& stepper, double radius, const BenchTilesOptions& o) {
  const auto p = stepper.params();
  const double dt = kLambda * p.h() / p.waveSpeed;
  gpu::GpuTimer timer(ctx, 1);
  std::vector<double> ms, fractions;
  for (uint32_t r = 0; r < o.repeats; ++r) {
    stepper.reset(sim::flatState(p.n, kLevel));
    stepper.step(1, dt);  // a reset marks every tile: settle that outside the timing
    if (radius > 0.0) stepper.drop({float(0.5 * p.extent), float(0.5 * p.extent)}, float(radius * p.extent), kAmplitude);
    stepper.readTilesDispatched();
    const auto start = std::chrono::steady_clock::now();
    gpu::submitAndWait(ctx, [&](const vk::raii::CommandBuffer& cmd) {
      timer.reset(cmd);
      const uint32_t scope = timer.begin(cmd, "steps");
      stepper.recordSteps(cmd, o.steps, dt);
      timer.end(cmd, scope);
    }, "benchmark");
    double milliseconds = timer.read().front().milliseconds;
    if (std::isnan(milliseconds)) {
      milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    ms.push_back(milliseconds / o.steps);
    const uint64_t all = stepper.kernel() == sim::StepKernel::ActiveTiles ? stepper.tiles().count() : 0;
    fractions.push_back(all ? double(stepper.readTilesDispatched().total()) / (double(o.steps) * double(all)) : 1.0);
  }
  return {median(ms), median(fractions)};
}

struct Row {
  unsigned n;
  double radius;
  Timed full, active, plain;
  bool ruleActive;
};

// The active fraction at which active and full take the same time, linear
// between the measured points around the first crossing (none: nullopt).
std::optional<double> crossover(const std::vector<Row>& rows, unsigned n) {
  const Row* previous = nullptr;
  for (const Row& r : rows) {
    if (r.n != n) continue;
    if (previous && previous->active.msPerStep <= previous->full.msPerStep && r.active.msPerStep > r.full.msPerStep) {
      const double d0 = previous->active.msPerStep - previous->full.msPerStep, d1 = r.active.msPerStep - r.full.msPerStep;
      const double f0 = previous->active.activeFraction, f1 = r.active.activeFraction;
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
      Row row{.n = n, .radius = radius, .full = {}, .active = {}, .plain = {}, .ruleActive = false};
      tiles.setTileDispatch(sim::TileDispatch::Full);
      row.full = timeSteps(ctx, tiles, radius, o);
      tiles.setTileDispatch(sim::TileDispatch::Active);
      row.active = timeSteps(ctx, tiles, radius, o);
      row.plain = timeSteps(ctx, plain, radius, o);
      row.ruleActive = sim::preferActiveList(n, uint32_t(std::lround(row.active.activeFraction * tiles.tiles().count())),
                                             tiles.tiles().count());
      rows.push_back(row);
      std::fprintf(stderr, "bench tiles: grid %u, drop radius %.3g measured\n", n, radius);
    }
  }

  io::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "grid,drop_radius,active_fraction,ms_full,ms_active,ms_one_per_dispatch,active_over_full,rule,device\n";
  std::printf("%6s %8s %8s %10s %10s %10s %8s %7s\n", "grid", "radius", "active", "full ms", "active ms", "plain ms",
              "act/full", "rule");
  for (const Row& r : rows) {
    const double ratio = r.active.msPerStep / r.full.msPerStep;
    const char* rule = r.ruleActive ? "active" : "full";
    std::printf("%6u %8.3g %8.3f %10.4f %10.4f %10.4f %8.3f %7s\n", r.n, r.radius, r.active.activeFraction,
                r.full.msPerStep, r.active.msPerStep, r.plain.msPerStep, ratio, rule);
    csv << r.n << "," << formatNumber("%.4g", r.radius) << "," << formatNumber("%.4g", r.active.activeFraction) << ","
        << formatNumber("%.6g", r.full.msPerStep) << "," << formatNumber("%.6g", r.active.msPerStep) << ","
        << formatNumber("%.6g", r.plain.msPerStep) << "," << formatNumber("%.4g", ratio) << "," << rule << ",\""
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
  csv.close();
  if (!csv) throw std::runtime_error("cannot write " + o.csv);
  csvFile.commit();
  std::printf("wrote %s\n", o.csv.c_str());
  if (!o.plot.empty()) plotCsv("plot_bench_tiles.py", o.csv, o.plot);
  return session.finish();
}

}  // namespace tp::app
