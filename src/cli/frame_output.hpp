#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "base/rational.hpp"
#include "cli/render_command.hpp"
#include "io/image_io.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tp::app {

// Whether --aov asked for `name`.
bool wants(const std::vector<std::string>& aovs, const char* name);

// What `render` asks of the renderer for its options: the AOV targets, the
// skipping, and each frame's readbacks (HDR, the PNG's LDR, the AOVs).
struct RasterPlan {
  render::RendererOptions renderer;
  render::FrameRequest request;  // its frame number is the caller's to set
};
// Throws one line when --aov asks for the AO channels and the SSAO passes do
// not run (--reference, --no-ao, a scene with ao.enabled false).
RasterPlan rasterPlan(const RenderOptions& o, const scene::Scene& scene);

// A scene's frames per second, 1 / water.frame_time, as the rational video
// rate an EXR's framesPerSecond holds (30/1, 30000/1001).
base::Rational sceneFrameRate(const scene::Scene& scene);

// The attributes of a rendered frame's EXR, `render`'s and the viewer's
// alike: the camera, Rec.709 primaries, the software, the frame number and
// the scene's frame rate; the compression left at its default.
io::ExrAttributes frameExrAttributes(const scene::Scene& scene, const render::RenderedFrame& frame,
                                     uint32_t frameNumber);

// Writes a rendered frame as `render` writes it: an EXR at `exr` unless it
// is empty (RGBA, half unless --float, then the AOVs asked for as float
// channels, with the camera, colour, software and frame attributes, in
// --compression; ao_ref ray traced here from the frame's G-buffer), and the
// tonemapped PNG at `png` unless it is empty; each through a temporary file.
void writeFrame(const RenderOptions& o, const scene::Scene& scene, const render::RenderedFrame& frame,
                uint32_t frameNumber, const std::string& exr, const std::string& png);

}  // namespace tp::app
