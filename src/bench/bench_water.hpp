#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "cli/scene_options.hpp"

namespace tp::app {

struct BenchWaterOptions {
  SceneSource scene;  // --scene and --set; no file: the built-in scene
  std::vector<std::string> resolutions{"160x90", "320x180", "640x360"};
  uint32_t frame = 10;
  uint32_t samples = 16;  // of the reference
  uint32_t repeats = 5;   // timed frames per case (the median is reported)
  std::string csv = "bench_water.csv";
  std::string plot = "bench_water.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
};

// `tidepool bench water`: each refraction mode (accurate, apparent) on a fixed
// set of views at several resolutions: GPU ms of the water passes and of the
// frame, error against the CPU reference (RMSE of the tonemapped image, over
// the frame and on the water) and the mean distance in pixels between where a
// mode reads the floor through the water and where the exact refracted ray
// meets it; a table, CSV and a plot of error against time.
int runBenchWater(const BenchWaterOptions& options);

}  // namespace tp::app
