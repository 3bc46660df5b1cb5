#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "viewer/view_session.hpp"

namespace tp::app {

// A drop the scripted run makes just before it renders the frame shown
// `frame`-th (that frame shows the water one frame after it): a testing aid.
struct ScriptedDrop {
  uint32_t frame = 0;
  scene::Drop drop;
};

// A window size the scripted run asks for just before the frame shown `frame`-th.
struct ScriptedResize {
  uint32_t frame = 0;
  uint32_t width = 0, height = 0;
};

// A command the scripted run applies, through the handler the keyboard and
// mouse reach (ViewSession::apply), just before it renders the frame shown
// `frame`-th (counting from 0: with a pause, not the frame number).
struct ScriptedCommand {
  uint32_t frame = 0;
  ViewCommand command;
};

struct ViewConfig {
  scene::Scene scene;
  uint32_t width = 1280, height = 720;  // the frame's size, and the window's at first
  std::optional<uint32_t> frames;       // stop after this many frames shown; none: run until closed
  std::string screenshot;               // with `frames`: save the last frame shown here (.exr float or .png)
  std::vector<ScriptedDrop> drops;
  std::optional<ScriptedResize> resize;
  std::vector<ScriptedCommand> script;  // in the order they apply
  std::string saveDir;                  // where Save writes view-NNNN.exr; empty: the working directory
  std::string shaderDir;                // the GLSL sources the reload key compiles
  bool panel = true;                    // the ImGui panel shows at first
  std::optional<double> targetFps;      // dynamic resolution (ResolutionGovernor): frames per second to hold
  bool profile = false;                 // print the last frame's passes at the end
  bool validate = false;
  std::string device;
};

// Opens the window and shows frames 0, 1, 2, ... of the scene, one frame
// number per frame shown (held while paused), taking the keyboard and mouse
// (app/view_input) and the script, until the window is closed or `frames`
// were shown; then writes the screenshot. Returns the exit code (GpuSession::finish);
// throws one line on failure, a window closed before the screenshot's frame
// included.
int runViewer(const ViewConfig& config);

}  // namespace tp::app
