#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "sim/wake_run.hpp"

namespace tp::app {

struct BenchWakeOptions {
  std::vector<uint32_t> sizes{64, 128, 256};
  std::vector<double> speeds{0.2, 0.5, 0.9};              // of the wave speed
  std::vector<double> gridDampings{0.0, 2.0, 5.0};        // kappa, 1/s
  std::vector<std::string> forcings{"column", "spread"};  // the forcing methods compared
  // The spread forcing's widening per metre of depth; the column forcing has none.
  std::vector<double> spreadDepthFactors{sim::kSpreadDepthFactor};
  // The spread forcing's widening near the wave speed (sim::wakeWidening): "on", "off".
  std::vector<std::string> nearSpeedWidening{"on"};
  std::vector<double> maxSlopes{0.0};            // the slope limiter (water.max_slope); 0: off
  double waveSpeed = sim::WakeCase{}.waveSpeed;  // c, m/s: the default scene's
  std::string csv = "bench_wake.csv";
  std::string plot = "bench_wake.png";
  bool validate = false;
  std::string device;
};

// `tidepool bench wake`: a sphere of the default scene's size crossing the
// default pool (sim/wake_run.hpp), half in and fully under the water, at each
// grid size, speed, grid damping and forcing: the share of the height variance above
// half the Nyquist wavenumber, the steepest slope, the highest crest and
// deepest trough against the wall milliseconds per step (forcing and step).
// The spread forcing runs once per widening in spreadDepthFactors; every run
// once per slope limit in maxSlopes. A table, CSV and a plot.
int runBenchWake(const BenchWakeOptions& options);

}  // namespace tp::app
