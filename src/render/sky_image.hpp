#pragma once
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gpu/memory.hpp"
#include "shading/sky_model.hpp"

namespace tp::render {

// An equirectangular environment read from .exr or .hdr (RGB, linear).
struct SkyImage {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec4> texels;  // rows top (zenith) to bottom
};

// Throws one line naming the file: unreadable, fewer than 3 channels, or non-finite texels.
SkyImage loadSkyImage(const std::string& path);

// The scene's image sky as it lights the scene: sky.image turned by
// sky.rotation and scaled by sky.intensity (placeSkyImage).
SkyImage loadSkyImage(const scene::Sky& sky);

// `image` turned by `degrees` about +y, from +x towards +z as sky.sun_azimuth
// turns (what was at azimuth a is at a + degrees), and scaled by
// `intensity`. A turn about the vertical shifts each row along u: exact for
// a whole number of texels, linear between two texels otherwise.
SkyImage placeSkyImage(const SkyImage& image, float degrees, float intensity);

// Radiance along unit direction d, bilinear between texel centres, wrapping
// around in u and clamped in v, as the renderer's sampler reads the texture.
glm::vec3 skyImageRadiance(const SkyImage& image, glm::vec3 d);

// The sky's radiance along unit d without the sun's disc: the image's
// (skyImageRadiance) where there is one, else the procedural sky's.
glm::vec3 skyRadianceWithout(const shader::SkyParams& procedural, const SkyImage* image, glm::vec3 d);

// The texture the sky pass fills from the procedural sky (sun included),
// `width` x width / 2 texels at their centres, as the half floats it holds.
SkyImage proceduralSkyImage(const scene::Sky& sky, uint32_t width);

// A half-float sampled texture holding the image in its level 0 (the other
// `mipLevels` are the caller's to fill), left in the shader-read layout.
gpu::Image uploadSkyImage(const gpu::Context& ctx, const SkyImage& image, const char* name = "sky image texture",
                          uint32_t mipLevels = 1);

}  // namespace tp::render
