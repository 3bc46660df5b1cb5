#pragma once
#include "scene/scene.hpp"
#include "shading/sky_model.hpp"
#include "shared/frame.h"

namespace tp::render {

// Fills the per-frame uniforms: camera matrices for a width x height image and
// the light (the procedural sky's, when none is given).
shader::FrameUniforms frameUniforms(const scene::Scene& scene, const SkyLight& light, uint32_t width, uint32_t height);
shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height);

}  // namespace tp::render
