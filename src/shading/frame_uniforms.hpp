#pragma once
#include "scene/scene.hpp"
#include "shading/sky_irradiance.hpp"
#include "shading/sky_model.hpp"
#include "shared/frame.h"

namespace tp::render {

// Whether anything in the scene casts the sun's shadow (render.shadows on,
// and an opaque sphere, a box, a glass sphere or a pool): otherwise the surfaces' shaders
// are the variants without the shadows' code.
bool castsShadows(const scene::Scene& scene);
// Whether the scene's opaque spheres, and its boxes, cast the sun's shadow:
// otherwise the shaders are specialized without their code
// (shared/sun_shadow.h's kSphereShadows and kBoxShadows).
bool spheresCastShadows(const scene::Scene& scene);
bool boxesCastShadows(const scene::Scene& scene);

// What casts the sun's shadows at `time`: the scene's opaque spheres (the
// first TP_MAX_SPHERES) where their paths put them, its boxes, its pool's
// walls, its glass spheres in the air (glassCasters); nothing with
// render.shadows off.
shader::ShadowCasters shadowCasters(const scene::Scene& scene, float time);

// The light a scene's frames are lit by, made once where its sky is: the
// sun (the procedural sky's; none under an image sky) and the irradiance of
// `sky` (its radiance, without the sun's disc) above the horizon with the
// ground's light below it, a uniform radiance: the ground's mean albedo
// times its irradiance from the sun (unshadowed) and the sky, over pi. That
// lights the undersides of objects and the walls' lower parts.
SkyLight sceneLight(const scene::Scene& scene, const SkyRadiance& sky);

// Fills the per-frame uniforms but for the shadows (none: the caller's to
// set, from shadowCasters): camera matrices for a width x height image and
// the light (sceneLight of the procedural sky, when none is given). `pixelOffset` moves where each pixel
// samples the image, in pixels from its centre (x right, y
// down): the jitter of an anti-aliased frame's samples; `filterWidth` the
// width in pixels textures are filtered over (FrameUniforms::sampling).
shader::FrameUniforms frameUniforms(const scene::Scene& scene, const SkyLight& light, uint32_t width, uint32_t height,
                                    glm::vec2 pixelOffset = glm::vec2(0.0f), float filterWidth = 1.0f);
shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height);

}  // namespace tp::render
