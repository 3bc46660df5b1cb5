#pragma once
#include <cstdint>
#include "gpu/vulkan.hpp"

#include "scene/scene.hpp"
#include "shared/ssao.h"

namespace tp::render {

// The one place where the scene's AO settings become the shaders' parameters.
//
// Kernel, pattern "hammersley": point i of the 3D Hammersley set,
// ((i + 1/2)/n, phi_2(i), phi_3(i)), its radical inverses in bases 2 and 3
// mapped to the cosine-weighted hemisphere, at a length growing as
// lerp(0.1, 1, ((i + 1/2)/n)^2) so that more samples lie near the origin.
// Noise tile: rotation angles 2 pi phi_2(k) for its texels.
// Pattern "random" is LearnOpenGL's: directions (2r-1, 2r-1, r) normalised,
// times r, times lerp(0.1, 1, (i/n)^2); noise (2r-1, 2r-1, 0); r from a
// Mersenne twister with a fixed seed, so the baseline is the same every run.
shader::SsaoKernel ssaoKernel(const scene::Ao& ao);

// Frame pixels per AO pixel along each axis: 1 at full resolution, 2 at half.
uint32_t aoFactor(const scene::Ao& ao);
// The AO image's size for a frame of width x height.
vk::Extent2D aoExtent(const scene::Ao& ao, uint32_t width, uint32_t height);

shader::SsaoParams ssaoParams(const scene::Ao& ao, uint32_t width, uint32_t height);
// One direction (0: x, 1: y) of the blur; taps centred on the pixel (an even
// count leans one pixel back, as the original's 4x4 box does).
shader::AoBlurParams aoBlurParams(const scene::Ao& ao, uint32_t direction, uint32_t width, uint32_t height);
shader::AoUpsampleParams aoUpsampleParams(const scene::Ao& ao, uint32_t width, uint32_t height);

}  // namespace tp::render
