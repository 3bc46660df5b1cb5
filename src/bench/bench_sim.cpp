#include "bench/bench_sim.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "bench/time_steps.hpp"
#include "cli/gpu_session.hpp"
#include "gpu/timer.hpp"
#include "sim/cpu_stepper.hpp"
#include "sim/exact_mode.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::app {
namespace {

constexpr double kLambda = 0.5;       // Courant number of every run
constexpr double kErrorTime = 0.125;  // seconds of simulated time for the error figures
constexpr int kModeM = 2, kModeN = 1;

struct Method {
  std::string name;
  bool gpu = true;
  sim::StepKernel kernel = sim::StepKernel::Tiled;
  uint32_t halo = 1;
};

struct Result {
  double seconds = 0.0;  // accumulated over iterations
  uint64_t steps = 0;
};

sim::WaterParams paramsFor(unsigned n) { return sim::WaterParams{.n = n, .extent = 1.0, .waveSpeed = 1.0}; }
double dtFor(unsigned n) { return kLambda * paramsFor(n).h(); }

sim::WaterState modeStart(unsigned n) {
  auto s = sim::modeState(n, 1.0, kModeM, kModeN, 1.0);
  sim::startAtRest(s, paramsFor(n), dtFor(n));
  return s;
}

// Steps per timed iteration: about 2^26 cell updates, and at most 1024
// dispatches in one command buffer.
uint64_t stepsPerIteration(unsigned n, const Method& m) {
  const uint64_t byWork = std::max<uint64_t>(4, (uint64_t(1) << 26) / (uint64_t(n) * n));
  const uint64_t perDispatch = m.gpu && m.kernel == sim::StepKernel::Tiled ? m.halo : 1;
  return std::min<uint64_t>(byWork, 1024 * perDispatch);
}

class QuietReporter : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>&) override {}
};

using Results = std::map<std::pair<unsigned, size_t>, Result>;  // per grid side and method
using Errors = std::map<unsigned, std::pair<double, double>>;   // per grid side: discrete, continuous

// Each method on each grid, timed by Google Benchmark for at least `minTime` seconds.
Results timeMethods(const gpu::Context& ctx, const std::vector<unsigned>& sizes, const std::vector<Method>& methods,
                    double minTime) {
  Results results;

  for (unsigned n : sizes) {
    for (size_t mi = 0; mi < methods.size(); ++mi) {
      const Method m = methods[mi];
      const std::string name = m.name + "/" + std::to_string(n);
      auto* b = benchmark::RegisterBenchmark(name.c_str(), [&, n, mi, m](benchmark::State& state) {
        const uint64_t steps = stepsPerIteration(n, m);
        const double dt = dtFor(n);
        Result& r = results[{n, mi}];
        if (m.gpu) {
          sim::GpuStepper stepper(ctx, paramsFor(n), modeStart(n), m.kernel, m.halo);
          gpu::GpuTimer timer(ctx, 1);
          for (auto _ : state) {
            const double seconds = timeSteps(ctx, timer, stepper, steps, dt);
            state.SetIterationTime(seconds);
            r.seconds += seconds;
            r.steps += steps;
          }
        } else {
          sim::CpuStepper stepper(paramsFor(n), modeStart(n));
          for (auto _ : state) {
            auto start = std::chrono::steady_clock::now();
            stepper.steps(steps, dt);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            state.SetIterationTime(seconds);
            r.seconds += seconds;
            r.steps += steps;
          }
        }
      });
      b->UseManualTime()->MinTime(minTime)->Unit(benchmark::kMillisecond);
    }
  }
  std::fprintf(stderr, "bench sim: %zu cases on %s, at least %.2g s each\n", sizes.size() * methods.size(),
               ctx.deviceName().c_str(), minTime);
  QuietReporter quiet;
  benchmark::RunSpecifiedBenchmarks(&quiet);
  benchmark::ClearRegisteredBenchmarks();

  return results;
}

// Error against the exact discrete and the continuous mode after kErrorTime
// seconds (the tiled kernel: bit-identical to the one-step kernel; the CPU
// loop differs from both by round-off only).
Errors modeErrors(const gpu::Context& ctx, const std::vector<unsigned>& sizes) {
  Errors errors;
  for (unsigned n : sizes) {
    const auto p = paramsFor(n);
    const double dt = dtFor(n);
    const uint64_t steps = uint64_t(std::llround(kErrorTime / dt));
    const sim::ExactMode mode{p, kModeM, kModeN, 1.0, dt};
    const auto u0 = sim::modeState(n, 1.0, kModeM, kModeN, 1.0);
    sim::GpuStepper stepper(ctx, p, modeStart(n), sim::StepKernel::Tiled, 4);
    stepper.step(steps, dt);
    const auto s = stepper.download();
    double discrete = 0.0, continuous = 0.0;
    for (size_t k = 0; k < s.u.size(); ++k) {
      discrete = std::max(discrete, std::abs(s.u[k] - mode.discreteFactorAtRest(double(steps)) * u0.u[k]));
      continuous = std::max(continuous, std::abs(s.u[k] - mode.continuousFactor(double(steps)) * u0.u[k]));
    }
    errors[n] = {discrete, continuous};
    std::fprintf(stderr, "bench sim: error of grid %u measured (%llu steps)\n", n,
                 static_cast<unsigned long long>(steps));
  }

  return errors;
}

// The table on stdout and the CSV (and its plot).
void writeTable(const BenchSimOptions& o, const gpu::Context& ctx, const std::vector<Method>& methods,
                const Results& results, const Errors& errors) {
  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "grid,method,steps_per_dispatch,ms_per_step,mcells_per_s,speedup_vs_cpu,error_exact_discrete,error_continuous,"
         "device\n";
  std::printf("%6s  %-28s %10s %12s %9s %14s %14s\n", "grid", "method", "ms/step", "Mcells/s", "vs CPU", "err discrete",
              "err continuous");
  for (unsigned n : o.sizes) {
    const Result& cpu = results.at({n, methods.size() - 1});
    const double cpuRate = double(cpu.steps) * n * n / cpu.seconds;
    for (size_t mi = 0; mi < methods.size(); ++mi) {
      const Result& r = results.at({n, mi});
      const double msPerStep = 1e3 * r.seconds / double(r.steps);
      const double rate = double(r.steps) * n * n / r.seconds;
      const auto [discrete, continuous] = errors.at(n);
      std::printf("%6u  %-28s %10.4f %12.1f %8.2fx %14.3g %14.3g\n", n, methods[mi].name.c_str(), msPerStep, rate / 1e6,
                  rate / cpuRate, discrete, continuous);
      csv << n << "," << methods[mi].name << ","
          << (methods[mi].kernel == sim::StepKernel::Tiled && methods[mi].gpu ? methods[mi].halo : 1) << ","
          << formatNumber("%.6g", msPerStep) << "," << formatNumber("%.6g", rate / 1e6) << ","
          << formatNumber("%.4g", rate / cpuRate) << "," << formatNumber("%.6g", discrete) << ","
          << formatNumber("%.6g", continuous) << ",\"" << ctx.deviceName() << "\"\n";
    }
  }
  commitBenchCsv(csvFile, csv, "plot_bench_sim.py", o.plot);
}

}  // namespace

int runBenchSim(const BenchSimOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  for (unsigned n : o.sizes) {
    if (n < 16 || n > sim::maxGrid(ctx)) {
      throw std::runtime_error("bench grid " + std::to_string(n) + " is outside 16.." +
                               std::to_string(sim::maxGrid(ctx)) + " on " + ctx.deviceName());
    }
  }

  std::vector<Method> methods{{"gpu one step per dispatch", true, sim::StepKernel::OnePerDispatch, 1},
                              {"gpu tiled halo 2", true, sim::StepKernel::Tiled, 2},
                              {"gpu tiled halo 4", true, sim::StepKernel::Tiled, 4},
                              {"gpu tiled halo 8", true, sim::StepKernel::Tiled, 8},
                              {"cpu openmp x" + std::to_string(sim::CpuStepper::threads()), false}};
  const Results results = timeMethods(ctx, o.sizes, methods, o.minTime);
  const Errors errors = modeErrors(ctx, o.sizes);
  writeTable(o, ctx, methods, results, errors);
  return session.finish();
}

}  // namespace tp::app
