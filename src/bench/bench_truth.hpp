#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace tp::app {

struct BenchTruthOptions {
  // Scene files, or "default" for the built-in scene.
  std::vector<std::string> scenes{"default"};
  std::string resolution = "160x90";
  uint32_t frame = 0;
  uint32_t samples = 256;       // paths per pixel of the path-traced truth
  uint32_t rasterSamples = 16;  // jittered frames the raster averages
  std::string csv = "bench_truth.csv";
  std::string plot = "bench_truth.png";
  bool validate = false;
  std::string device;
};

// `tidepool bench truth`: each scene rendered by the raster (its samples
// averaged, as `render --samples` draws) and path-traced on the CPU (the
// truth, reference/path_tracer: the mean of two seeds, their difference
// its noise), with each one's wall time and the raster's
// tonemapped error over the frame and over the regions whose light differs:
// the pool (its water, floor and walls), the objects, the rest of the
// ground. A table, CSV and a plot.
int runBenchTruth(const BenchTruthOptions& options);

}  // namespace tp::app
