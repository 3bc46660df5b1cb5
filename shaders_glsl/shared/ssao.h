// Screen-space ambient occlusion: the kernel and noise tile (a uniform buffer
// filled once per renderer, render/ssao_model.cpp), the push constants of the
// SSAO, blur, upsample and apply passes, and the one reconstruction of a
// view-space position from the depth buffer, declared once for C++ and GLSL.
#ifndef TP_SHARED_SSAO_H
#define TP_SHARED_SSAO_H
#include "shared/interop.h"

#define TP_MAX_SSAO_KERNEL 64
#define TP_MAX_SSAO_NOISE 64  // texels of the rotation tile: up to 8 x 8

TP_BEGIN

struct SsaoKernel {
  vec4 samples[TP_MAX_SSAO_KERNEL];  // xyz: tangent-space offsets in the unit hemisphere (z along the normal)
  vec4 noise[TP_MAX_SSAO_NOISE];     // xy: rotation vectors in the tangent plane, tiled over the screen
};

// The AO image has one pixel per `factor` x `factor` block of the frame (1:
// full resolution, 2: half); AO pixel p stands for frame pixel p * factor.
struct SsaoParams {
  uvec4 config;  // x: kernel size, y: noise tile side, z: factor, w: 1 interpolate the depth at samples, 0 nearest
  uvec4 size;    // xy: AO image size, zw: frame (depth buffer) size
  vec4 shape;    // x: radius (m), y: depth bias (m); zw unused
};

// One direction of the separable blur: taps at offsets first .. first + taps - 1.
struct AoBlurParams {
  uvec4 config;  // x: 0 horizontal, 1 vertical; y: taps; z: 1 bilateral (depth-aware), 0 box; w unused
  ivec4 window;  // x: offset of the first tap (pixels); yzw unused
  uvec4 size;    // xy: AO image size
  vec4 shape;    // x: depth tolerance of the bilateral weight, relative to the pixel's view depth
};

// The depth-aware upsample of half-resolution AO to the frame.
struct AoUpsampleParams {
  uvec4 size;  // xy: frame size, zw: AO image size
  vec4 shape;  // x: depth tolerance, relative to the frame pixel's view depth; y: factor
};

// Push constants of the pass that puts the AO into the frame.
struct AoApplyParams {
  uvec4 size;  // xy: image size
};

// The view-space position of the surface at texture coordinate uv (0 at the
// top-left corner of the frame, 1 at the bottom-right) and depth-buffer value
// `depth`: the original's reconstruction, clip coordinates back through the
// inverse projection.
TP_INLINE vec3 viewPositionFromDepth(mat4 inverseProjection, vec2 uv, float depth) {
  const vec4 p = inverseProjection * vec4(uv.x * 2.0f - 1.0f, uv.y * 2.0f - 1.0f, depth, 1.0f);
  return vec3(p.x, p.y, p.z) / p.w;
}

// A pixel's colour with the AO taken from its ambient part: the surfaces'
// passes drew direct light plus ambient (the sky's irradiance) and kept the
// ambient part apart; AO scales only that part.
TP_INLINE vec3 withAo(vec3 color, vec3 ambient, float ao) { return color - ambient * (1.0f - ao); }

// What the SSAO pass stores of each AO pixel's surface for the passes after
// it (the blur, the upsample): its distance in front of the camera, which
// for a perspective projection does not depend on the pixel's x and y; and
// where no surface is (depth 1), the far plane's distance negated. One
// image read then stands for a depth fetch and a reconstruction.
TP_INLINE float aoViewDepth(mat4 inverseProjection, float depth) {
  const float d = -viewPositionFromDepth(inverseProjection, vec2(0.5f), depth).z;
  return depth < 1.0f ? d : -d;
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SsaoKernel) == 16 * (TP_MAX_SSAO_KERNEL + TP_MAX_SSAO_NOISE));
static_assert(sizeof(tp::shader::SsaoParams) == 48);
static_assert(sizeof(tp::shader::AoBlurParams) == 64);
static_assert(sizeof(tp::shader::AoUpsampleParams) == 32);
static_assert(sizeof(tp::shader::AoApplyParams) == 16);
#endif

#endif
