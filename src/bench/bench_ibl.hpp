#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "cli/scene_options.hpp"

namespace tp::app {

struct BenchIblOptions {
  SceneSource scene;      // --scene and --set; no file: the built-in scene
  uint32_t width = 1024;  // environment texels across (height: half)
  std::vector<uint32_t> samples{16, 64, 256, 1024, 4096, 16384, 65536};
  uint32_t rotations = 8;  // independent sample sets per case (errors: RMS over them)
  uint32_t repeats = 5;    // timed CDF builds (the median is reported; the SH estimate: over the rotations)
  std::string csv = "bench_ibl.csv";
  std::string plot = "bench_ibl.png";
  // The glossy prefilter (render/glossy_prefilter): samples per texel, split
  // between environment and lobe (MIS) or all of one kind; empty: not measured.
  std::vector<uint32_t> glossySamples{16, 64, 128, 256, 1024};
  std::string glossyCsv = "bench_ibl_glossy.csv";
  std::string glossyPlot = "bench_ibl_glossy.png";
  bool validate = false;
  std::string device;
};

// `tidepool bench ibl`: the scene's procedural sky with its sun as an
// equirectangular environment; its SH9 irradiance estimated on the GPU
// (render/env_prefilter) from N samples drawn by importance (the luminance
// CDFs) or uniformly over the sphere: GPU ms of the estimate and of the CDF
// build against the error of the irradiance from the exact texel-by-texel
// projection (worst over 100 normals, relative to the brightest, RMS over
// the rotations); and the CPU ms of that exact projection. A table, CSV and a plot.
// Then the glossy prefilter of the same sky (its map at most 512 wide):
// per sampling strategy and samples per texel, the GPU ms of the whole map
// (CDFs and every level) against each level's error from the exact
// quadrature (render/glossy_quadrature) at 256 texels of the level. A
// second table, CSV and plot.
int runBenchIbl(const BenchIblOptions& options);

}  // namespace tp::app
