#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace tp::app {

struct BenchTilesOptions {
  std::vector<unsigned> sizes{256, 512, 1024};
  // Drop radius as a fraction of the grid side; 0: calm water (no drop).
  std::vector<double> radii{0.0, 0.01, 0.03, 0.06, 0.1, 0.15, 0.2, 0.3, 0.35, 0.4, 0.45, 0.75};
  uint32_t steps = 16;   // steps per timed submission, right after the drop
  uint32_t repeats = 5;  // timed submissions per case (the median is reported)
  std::string csv = "bench_tiles.csv";
  std::string plot = "bench_tiles.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
};

// `tidepool bench tiles`: ms per step of the active-tile stepper dispatching
// every tile (full) and only the listed ones (active), and of the plain
// one-step kernel, against the fraction of tiles active (a drop of growing
// radius on calm water), per grid size; the crossover of active and full per
// grid, and what the dispatch rule (sim::preferActiveList) picks. A table,
// CSV and a plot.
int runBenchTiles(const BenchTilesOptions& options);

}  // namespace tp::app
