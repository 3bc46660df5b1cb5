#include "bench/bench_wake.hpp"

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "cli/gpu_session.hpp"
#include "sim/wake_run.hpp"

namespace tp::app {

namespace {

// Every case the options name, in the table's order.
std::vector<sim::WakeCase> wakeCases(const BenchWakeOptions& o) {
  std::vector<sim::WakeCase> cases;
  for (const uint32_t grid : o.sizes) {
    for (const double speed : o.speeds) {
      for (const bool submerged : {false, true}) {
        for (const std::string& name : o.forcings) {
          const sim::SphereForcing forcing = sim::parseSphereForcing(name);
          // The column forcing has no widening: one run with the default's.
          const bool spread = forcing == sim::SphereForcing::Spread;
          const std::vector<double> widenings = spread ? o.spreadDepthFactors : std::vector{sim::kSpreadDepthFactor};
          const std::vector<std::string> nearSpeed = spread ? o.nearSpeedWidening : std::vector<std::string>{"on"};
          for (const double widening : widenings) {
            for (const std::string& near : nearSpeed) {
              for (const double kappa : o.gridDampings) {
                for (const double maxSlope : o.maxSlopes) {
                  cases.push_back({.grid = grid,
                                   .speedFraction = speed,
                                   .submerged = submerged,
                                   .gridDamping = kappa,
                                   .forcing = forcing,
                                   .spreadDepthFactor = widening,
                                   .widenNearWaveSpeed = near == "on",
                                   .maxSlope = maxSlope,
                                   .waveSpeed = o.waveSpeed});
                }
              }
            }
          }
        }
      }
    }
  }
  return cases;
}

}  // namespace

int runBenchWake(const BenchWakeOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "grid,speed_fraction,immersion,forcing,spread_depth_factor,near_speed_widening,grid_damping,slope_limit,"
         "steps,ms_per_step,high_share,max_slope,crest_m,trough_m,volume_change_m3,device\n";
  std::printf("%5s %6s %-9s %-7s %6s %4s %6s %6s %6s %8s %8s %7s %8s %8s\n", "grid", "speed", "immersion", "forcing",
              "widen", "near", "kappa", "limit", "steps", "ms/step", "high", "slope", "crest m", "trough m");
  for (const sim::WakeCase& c : wakeCases(o)) {
    const bool spread = c.forcing == sim::SphereForcing::Spread;
    const std::string name = sim::toString(c.forcing), widen = spread ? formatNumber("%.3g", c.spreadDepthFactor) : "-";
    const std::string near = spread ? (c.widenNearWaveSpeed ? "on" : "off") : "-";
    const char* immersion = c.submerged ? "submerged" : "half";
    std::fprintf(stderr,
                 "bench wake: grid %u, %.2f c, %s, %s forcing, widening %s, near the wave speed %s, kappa %g, "
                 "slope limit %g\n",
                 c.grid, c.speedFraction, c.submerged ? "submerged" : "half in", name.c_str(), widen.c_str(),
                 near.c_str(), c.gridDamping, c.maxSlope);
    const sim::WakeResult r = sim::runWake(ctx, c);
    const sim::WakeMeasures& m = r.measures;
    std::printf("%5u %5.2fc %-9s %-7s %6s %4s %6g %6g %6llu %8.3f %8.4f %7.3f %8.4f %8.4f\n", c.grid, c.speedFraction,
                immersion, name.c_str(), widen.c_str(), near.c_str(), c.gridDamping, c.maxSlope,
                static_cast<unsigned long long>(r.steps), 1e3 * r.secondsPerStep, m.highShare, m.maxSlope, m.crest,
                m.trough);
    csv << c.grid << "," << c.speedFraction << "," << immersion << "," << name << "," << (spread ? widen : "") << ","
        << (spread ? near : "") << "," << c.gridDamping << "," << c.maxSlope << "," << r.steps << ","
        << formatNumber("%.6g", 1e3 * r.secondsPerStep) << "," << formatNumber("%.6g", m.highShare) << ","
        << formatNumber("%.6g", m.maxSlope) << "," << formatNumber("%.6g", m.crest) << ","
        << formatNumber("%.6g", m.trough) << "," << formatNumber("%.3g", r.volumeChange) << ",\"" << ctx.deviceName()
        << "\"\n";
  }
  commitBenchCsv(csvFile, csv, "plot_bench_wake.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
