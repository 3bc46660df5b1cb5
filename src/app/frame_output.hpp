#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/render_command.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tp::app {

// Whether --aov asked for `name`.
bool wants(const std::vector<std::string>& aovs, const char* name);

// Writes a rendered frame as `render` writes it: an EXR at `exr` (RGBA, half
// unless --float, then the AOVs asked for as float channels, with the camera
// attributes; ao_ref ray traced here from the frame's G-buffer), and the
// tonemapped PNG at `png` unless it is empty; each through a temporary file.
void writeFrame(const RenderOptions& o, const scene::Scene& scene, const render::RenderedFrame& frame,
                uint32_t frameNumber, const std::string& exr, const std::string& png);

}  // namespace tp::app
