#pragma once
#include "scene/scene.hpp"
#include "shared/ssao.h"

namespace tp::render {

// The one place where the scene's AO settings become the shaders' parameters.
// The kernel: point i of the 3D Hammersley set (i + 1/2)/n, radical inverses in
// bases 2 and 3 mapped to the cosine-weighted hemisphere (bases 2 and 3), at a
// length growing as lerp(0.1, 1, ((i + 1/2)/n)^2) so that more samples lie near
// the origin. The noise tile: rotation angles 2 pi phi_2(k) for its texels.
shader::SsaoKernel ssaoKernel(const scene::Ao& ao);
shader::SsaoParams ssaoParams(const scene::Ao& ao, uint32_t width, uint32_t height);
// One direction (0: x, 1: y) of the blur; taps centred on the pixel (an even
// count leans one pixel back, as the original's 4x4 box does).
shader::AoBlurParams aoBlurParams(const scene::Ao& ao, uint32_t direction, uint32_t width, uint32_t height);

}  // namespace tp::render
