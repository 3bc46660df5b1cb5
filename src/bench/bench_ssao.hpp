#pragma once
#include <cstdint>
#include <string>
#include "cli/scene_options.hpp"

namespace tp::app {

struct BenchSsaoOptions {
  SceneSource scene;  // --scene and --set; no file: the built-in scene
  std::string resolution = "640x360";
  uint32_t frame = 10;
  uint32_t repeats = 5;  // timed frames per case (the median is reported)
  std::string csv = "bench_ssao.csv";
  std::string plot = "bench_ssao.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
};

// `tidepool bench ssao`: SSAO settings swept (kernel 4 to 64 samples, blur
// off / box / bilateral, full or half resolution) and the presets, on one
// frame: GPU ms of the AO passes against the error of the AO from the
// reference ray traced from the same G-buffer (mean absolute, RMS, worst
// pixel, and mean absolute over the pixels where the reference is under
// 0.95); the cases on the Pareto front of time against mean error are marked.
// A table, CSV and a plot.
int runBenchSsao(const BenchSsaoOptions& options);

}  // namespace tp::app
