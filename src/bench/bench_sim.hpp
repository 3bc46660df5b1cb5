#pragma once
#include <string>
#include <vector>

namespace tp::app {

struct BenchSimOptions {
  std::vector<unsigned> sizes{256, 512, 1024, 2048};
  std::string csv = "bench_sim.csv";
  std::string plot = "bench_sim.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
  double minTime = 0.5;  // seconds Google Benchmark spends on each case
};

// `tidepool bench sim`: cells/s of the GPU stepper (one step per dispatch, and
// tiled with several halos) and of the OpenMP C++ loop, per grid size, with
// the error against the exact and continuous mode; a table, CSV and a plot.
int runBenchSim(const BenchSimOptions& options);

}  // namespace tp::app
