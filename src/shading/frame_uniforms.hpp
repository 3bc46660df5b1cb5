#pragma once
#include "scene/scene.hpp"
#include "shading/sky_model.hpp"
#include "shared/frame.h"

namespace tp::render {

// Whether anything in the scene casts the sun's shadow (render.shadows on,
// and an opaque sphere, a box or a pool): otherwise the surfaces' shaders
// are the variants without the shadows' code.
bool castsShadows(const scene::Scene& scene);
// Whether the scene's opaque spheres, and its boxes, cast the sun's shadow:
// otherwise the shaders are specialized without their code
// (shared/sun_shadow.h's kSphereShadows and kBoxShadows).
bool spheresCastShadows(const scene::Scene& scene);
bool boxesCastShadows(const scene::Scene& scene);

// What casts the sun's shadows at `time`: the scene's opaque spheres (the
// first TP_MAX_SPHERES) where their paths put them, its boxes, its pool's
// walls; nothing with render.shadows off.
shader::ShadowCasters shadowCasters(const scene::Scene& scene, float time);

// The light the scene's ground sends up, as SH9 of a uniform radiance below
// the horizon: the ground's mean albedo near the pool (its hole left out)
// times its irradiance from the sun (unshadowed) and the sky, over pi.
// What lights the undersides of objects and the walls' lower parts; it adds
// nothing to a surface facing up (SH9's bands 0-2 of a lower hemisphere
// cancel there).
shader::Sh9 groundLightSh9(const scene::Scene& scene, const SkyLight& light);
// The sky's light with the ground's below the horizon added to its SH9:
// the light a scene's frames take, made once where the sky is.
SkyLight withGroundLight(const scene::Scene& scene, SkyLight light);

// Fills the per-frame uniforms but for the shadows (none: the caller's to
// set, from shadowCasters): camera matrices for a width x height image and
// the light (the procedural sky's with the ground's, withGroundLight, when
// none is given; as it is when given). `pixelOffset` moves where each pixel
// samples the image, in pixels from its centre (x right, y
// down): the jitter of an anti-aliased frame's samples; `filterWidth` the
// width in pixels textures are filtered over (FrameUniforms::sampling).
shader::FrameUniforms frameUniforms(const scene::Scene& scene, const SkyLight& light, uint32_t width, uint32_t height,
                                    glm::vec2 pixelOffset = glm::vec2(0.0f), float filterWidth = 1.0f);
shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height);

}  // namespace tp::render
