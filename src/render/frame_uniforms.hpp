#pragma once
#include "scene/scene.hpp"
#include "shared/frame.h"

namespace tp::render {

// Fills the per-frame uniforms: camera matrices for a width x height image and
// the sun and sky light of the scene.
shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height);

}  // namespace tp::render
