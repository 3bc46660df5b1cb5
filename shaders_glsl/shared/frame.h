// Per-frame camera and light, a uniform buffer filled in one place
// (render/frame_uniforms.cpp) and read by every pass that needs it.
#ifndef TP_SHARED_FRAME_H
#define TP_SHARED_FRAME_H
#include "shared/interop.h"
#include "shared/sky_irradiance.h"
#include "shared/shadow_casters.h"

TP_BEGIN

struct FrameUniforms {
  mat4 view;                   // world to camera (camera looks down -z)
  mat4 projection;             // camera to clip, Vulkan conventions (y down, depth 0..1)
  mat4 viewProjection;
  mat4 inverseViewProjection;
  vec4 cameraPosition;         // xyz world position
  vec4 sunDirection;           // xyz unit vector towards the sun
  vec4 sunIrradiance;          // rgb irradiance of the sun disk on a surface facing it
  vec4 viewport;               // width, height, 1/width, 1/height
  mat4 inverseProjection;      // clip to camera: view-space positions from the depth buffer
  SkyIrradiance skyIrradiance;  // the sky's light (without the sun) and the ground's: the irradiance (sky_irradiance.h)
  // x: the width in pixels that textures are filtered over: 1 for a frame on
  // its own, 1/sqrt(N) for one of N jittered samples (each sample's share of
  // the pixel), so the samples' average is the pixel's box filter, not a
  // box filtered twice. y: 0, always: the base of the indices some uniforms
  // are read by, which lavapipe cannot fold into a shader's code
  // (TP_UNIFORM_INDEX_BASE, below). zw unused.
  vec4 sampling;
  ShadowCasters shadows;  // what casts the sun's shadows (shadow_casters.h, sun_shadow.h)
};

TP_END

#ifndef __cplusplus
// Lavapipe folds the uniforms a shader's branches test into its code and
// compiles the shader again at every draw when that halves it ("inline
// uniforms", docs/sun-shadows.md#cost). A uniform read through an index it
// cannot fold stays a uniform: TP_UNIFORM_INDEX_BASE is frame.sampling.y,
// always 0, and TP_OPAQUE_ZERO, added to a value a branch tests, keeps that
// test's uniforms out of the folding. Both read the includer's `frame`.
#define TP_UNIFORM_INDEX_BASE int(frame.sampling.y)
#define TP_OPAQUE_ZERO frame.sampling[TP_UNIFORM_INDEX_BASE + 1]
#endif

#ifdef __cplusplus
static_assert(sizeof(tp::shader::FrameUniforms) == 5 * 64 + 5 * 16 + 31 * 16 + (3 + 4 * 4 + 2 * 4) * 16);
static_assert(offsetof(tp::shader::FrameUniforms, cameraPosition) == 256);
#endif

#endif
