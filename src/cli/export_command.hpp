#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "cli/scene_options.hpp"

namespace tp::app {

struct ExportOptions {
  SceneSource scene;  // --scene and --set
  uint32_t frame = 0;
  std::string frames;   // --frames A-B: a mesh sequence, one file per frame
  bool resume = false;  // with --frames: leave out the frames already written whole
  std::string out;
  bool validate = false;
  std::string device;
};

// `tidepool export`: the scene's triangles (water included) at a frame, or at
// each frame of a range, as OBJ (with its .mtl), PLY or binary glTF; a range
// stops after the frame being written on SIGINT or SIGTERM, as render's does.
CLI::App* addExportCommand(CLI::App& app, ExportOptions& options);
int runExport(const ExportOptions& options);

}  // namespace tp::app
