#pragma once
#include <cstdint>
#include <string>
#include "cli/scene_options.hpp"

namespace tp::app {

struct BenchFrameOptions {
  SceneSource scene;  // --scene and --set; no file: the built-in scene
  std::string resolution = "640x360";
  uint32_t frames = 20;  // timed frames of each sequence (after frame 0, which warms up)
  std::string csv = "bench_frame.csv";
  std::string plot = "bench_frame.png";
  bool validate = false;  // timings under validation are not representative
  std::string device;
};

// `tidepool bench frame`: variants of the scene (everything on, no water,
// calm water, AO off, objects out of view, camera over the water) rendered as
// a sequence of frames with skipping on and off (RendererOptions::skipping):
// median GPU ms per frame (the sum over its passes), median wall ms, and per
// frame the passes, dispatches, draws and workgroups recorded; the saving of
// skipping per variant. A table, CSV and a plot.
int runBenchFrame(const BenchFrameOptions& options);

}  // namespace tp::app
