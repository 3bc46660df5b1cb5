// Screen-space ambient occlusion: the kernel and noise tile (a uniform buffer
// filled once per renderer, render/ssao_model.cpp) and the push constants of
// the SSAO, blur and apply passes, declared once for C++ and GLSL.
#ifndef TP_SHARED_SSAO_H
#define TP_SHARED_SSAO_H
#include "shared/interop.h"

#define TP_MAX_SSAO_KERNEL 64
#define TP_MAX_SSAO_NOISE 64  // texels of the rotation tile: up to 8 x 8

TP_BEGIN

struct SsaoKernel {
  vec4 samples[TP_MAX_SSAO_KERNEL];  // xyz: tangent-space offsets in the unit hemisphere (z along the normal)
  vec4 noise[TP_MAX_SSAO_NOISE];     // xy: unit rotation vectors in the tangent plane, tiled over the screen
};

struct SsaoParams {
  uvec4 config;  // x: kernel size, y: noise tile side, zw: image size
  vec4 shape;    // x: radius (m), y: depth bias (m); zw unused
};

// One direction of the separable blur: taps at offsets first .. first + taps - 1.
struct AoBlurParams {
  uvec4 config;  // x: 0 horizontal, 1 vertical; y: taps; z: 1 bilateral (depth-aware), 0 box; w unused
  ivec4 window;  // x: offset of the first tap (pixels); yzw unused
  uvec4 size;    // xy: image size
  vec4 shape;    // x: depth tolerance of the bilateral weight, relative to the pixel's view depth
};

// Push constants of the pass that puts the AO into the frame.
struct AoApplyParams {
  uvec4 size;  // xy: image size
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SsaoKernel) == 16 * (TP_MAX_SSAO_KERNEL + TP_MAX_SSAO_NOISE));
static_assert(sizeof(tp::shader::SsaoParams) == 32);
static_assert(sizeof(tp::shader::AoBlurParams) == 64);
static_assert(sizeof(tp::shader::AoApplyParams) == 16);
#endif

#endif
