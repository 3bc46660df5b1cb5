#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/scene_options.hpp"

namespace tp::app {

struct RenderOptions {
  SceneChoice scene;  // --scene, --set, --no-ao, --preset
  uint32_t width = 1280;
  uint32_t height = 720;
  std::string size;        // --size WxH, resolved into width and height
  uint32_t oldWidth = 0;   // --width, the old spelling of --size's width; 0: not given
  uint32_t oldHeight = 0;  // --height, likewise
  uint32_t frame = 0;
  std::vector<std::string> outs;  // --out, each .exr or .png; none: render.exr
  std::string pngAlso;            // --png, the old spelling of a second --out PATH.png
  // The outputs resolveOutputs finds in outs and pngAlso; an empty one is not written.
  std::string exr;
  std::string png;
  bool floatOutput = false;
  bool halfOutput = false;
  bool validate = false;
  std::string device;
  bool profile = false;
  bool noSkip = false;            // record every pass (RendererOptions::skipping off)
  std::vector<std::string> aovs;  // Z, N, P, ao, ao_raw, ao_ref
  bool reference = false;         // path-trace on the CPU instead: the truth (reference/path_tracer)
  bool modelReference = false;    // trace the raster's own lighting model on the CPU (reference/reference_tracer)
  uint32_t seed = 0;              // the path tracer's
  double timeBudget = 0.0;        // seconds the path tracer may take (0: no limit)
  uint32_t samples = 0;           // per pixel: jittered frames, or rays with --reference; 0: the default (1, 64)
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

// The options with --size, --out and --png resolved into width, height, exr
// and png. Throws UsageError on an extension that names no format, two
// outputs of one format, or --aov without an EXR.
RenderOptions resolveOutputs(const RenderOptions& options);

// --samples for the raster, or its default: one frame.
uint32_t rasterSamples(const RenderOptions& options);

// Returns the process exit code; throws std::exception on failure.
int runRender(const RenderOptions& options);

}  // namespace tp::app
