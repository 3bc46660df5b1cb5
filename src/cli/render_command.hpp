#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/scene_options.hpp"

namespace tp::app {

struct RenderOptions {
  SceneChoice scene;  // --scene, --no-ao, --preset
  uint32_t width = 1280;
  uint32_t height = 720;
  uint32_t frame = 0;
  std::string out = "render.exr";
  std::string png;
  bool floatOutput = false;
  bool halfOutput = false;
  bool validate = false;
  std::string device;
  bool profile = false;
  bool noSkip = false;            // record every pass (RendererOptions::skipping off)
  std::vector<std::string> aovs;  // Z, N, P, ao, ao_raw, ao_ref
  bool reference = false;         // ray-trace on the CPU instead (render/reference_tracer)
  uint32_t samples = 64;          // per pixel, with --reference
  std::string frames;             // a range A-B: render each frame to the --out (and --png) pattern
  uint32_t checkpointEvery = 0;   // with frames: save the water every K frames in checkpointDir
  std::string checkpointDir;      // with frames: where checkpoints are saved and resumed from
  bool resume = false;            // with frames: leave out the frames whose files exist and are whole
  // How the EXR is written.
  std::string compression = "zip";  // one of io::exrCompressions()
  bool transparentSky = false;      // RGBA 0 where nothing is hit
};

// Adds `tidepool render` and its options to the command line.
CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options);

// Returns the process exit code; throws std::exception on failure.
int runRender(const RenderOptions& options);

}  // namespace tp::app
