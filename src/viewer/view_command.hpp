#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "cli/scene_options.hpp"

namespace tp::app {

struct ViewOptions {
  SceneChoice scene;  // --scene, --no-ao, --preset
  std::string size = "1280x720";
  uint32_t frames = 0;  // 0: run until the window is closed
  std::string screenshot;
  std::vector<std::string> scriptDrops;  // FRAME:X,Z,RADIUS,AMP
  std::string scriptResize;              // FRAME:WxH
  std::vector<std::string> script;       // FRAME:ACTION[:ARGS]
  std::string saveDir;
  std::string shaderDir;  // empty: base::dataDir's shaders_glsl (installed, or the checkout's)
  bool noPanel = false;
  double targetFps = 0.0;  // 0: off (the frame renders at --size)
  bool profile = false;
  bool validate = false;
  std::string device;
};

// Adds `tidepool view` and its options to the command line.
CLI::App* addViewCommand(CLI::App& app, ViewOptions& options);

// Returns the process exit code; throws std::exception on failure.
int runView(const ViewOptions& options);

}  // namespace tp::app
