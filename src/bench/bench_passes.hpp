#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "cli/scene_options.hpp"

namespace tp::app {

struct BenchPassesOptions {
  SceneSource scene;  // --scene and --set; no file: the built-in scene
  std::vector<std::string> resolutions{"1280x720", "640x360", "320x180"};
  uint32_t frames = 10;  // timed frames of each kind per resolution
  bool shown = false;    // time the viewer's frame: no HDR readback, the tonemapped image kept for showing
  std::string csv = "bench_passes.csv";
  std::string plot = "bench_passes.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
};

// `tidepool bench passes`: where a frame's time goes, by wall clock. At each
// resolution, after a first frame: `frames` frames submitted whole (their
// median wall time gives the frames per second), then `frames` more with
// each pass submitted and waited for on its own (FrameRequest::passWallTimes):
// each pass's median wall and GPU milliseconds. A table, CSV and a plot.
int runBenchPasses(const BenchPassesOptions& options);

}  // namespace tp::app
