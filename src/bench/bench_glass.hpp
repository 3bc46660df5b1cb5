#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "cli/scene_options.hpp"

namespace tp::app {

struct BenchGlassOptions {
  SceneSource scene;  // --scene and --set; no file: render::glassSphereView()
  std::string resolution = "320x180";
  std::vector<uint32_t> steps{1, 2, 4, 8, 16, 32};  // binary-search steps for the exit point
  uint32_t samples = 16;                            // of the reference
  uint32_t repeats = 5;                             // timed frames per case (the median is reported)
  std::string csv = "bench_glass.csv";
  std::string plot = "bench_glass.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
};

// `tidepool bench glass`: the glass spheres' image-space refraction with each
// number of binary-search steps: GPU ms of the two glass passes (median of
// repeats, at the resolution) against the error from the CPU reference's
// exact exit point (RMSE and largest error of the tonemapped image over the
// glass pixels, the raster supersampled 4x4 as the glass test compares it).
// A table, CSV and a plot.
int runBenchGlass(const BenchGlassOptions& options);

}  // namespace tp::app
