#pragma once
#include "scene/scene.hpp"
#include "shading/sky_model.hpp"
#include "shared/frame.h"

namespace tp::render {

// Fills the per-frame uniforms: camera matrices for a width x height image and
// the light (the procedural sky's, when none is given). `pixelOffset` moves
// where each pixel samples the image, in pixels from its centre (x right, y
// down): the jitter of an anti-aliased frame's samples; `filterWidth` the
// width in pixels textures are filtered over (FrameUniforms::sampling).
shader::FrameUniforms frameUniforms(const scene::Scene& scene, const SkyLight& light, uint32_t width, uint32_t height,
                                    glm::vec2 pixelOffset = glm::vec2(0.0f), float filterWidth = 1.0f);
shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height);

}  // namespace tp::render
