// Importance sampling of an equirectangular environment (W x H texels,
// piecewise constant): the pieces of the sampler that are pure arithmetic,
// compiled both as GLSL and as C++ (render/env_sampler builds the CDFs).
//
// Texel (i, j) is drawn with probability lum(i, j) * Omega(j) / sum, Omega(j)
// its solid angle (2pi / W) (cos theta_j - cos theta_j+1): the luminance
// weighted by sin(theta) integrated over the texel's row, rather than by the
// sin of the row's centre, so that a constant environment is sampled exactly
// uniformly over the sphere. Within the texel u is uniform and cos(theta) is
// uniform, so the solid-angle density is constant there: lum(i, j) / sum,
// which equals p(u, v) / (2 pi^2 sin theta) with p(u, v) the density of (u, v).
#ifndef TP_SHARED_ENV_SAMPLING_H
#define TP_SHARED_ENV_SAMPLING_H
#include "shared/equirect.h"
#include "shared/interop.h"

TP_BEGIN

// The push constants of the GPU sampler's passes (env_rows.comp,
// env_marginal.comp, env_sh.comp).
struct EnvParams {
  uvec4 size;      // environment width, height; z: samples; w: 1 draws uniformly over the sphere instead
  vec4 rotation;   // xy: the Cranley-Patterson rotation of the Hammersley set; zw unused
};

// Point k of the n-point Hammersley set ((k + 1/2) / n, the base-2 radical
// inverse of k: its bits mirrored about the binary point, times 2^-32),
// shifted by `rotation` modulo 1: fixed rotations give independent
// deterministic sets.
TP_INLINE vec2 envHammersley(uint k, uint n, vec2 rotation) {
  vec2 p = vec2((float(k) + 0.5f) / float(n), float(bitfieldReverse(k)) * 2.3283064365386963e-10f) + rotation;
  return p - floor(p);
}

// A direction uniform over the sphere for a point xi of the unit square (density 1 / 4pi).
TP_INLINE vec3 envUniformDirection(vec2 xi) { return equirectToDirectionCos(xi.y, 1.0f - 2.0f * xi.x); }

// Rec. 709 luminance of linear rgb: what the sampler follows.
TP_INLINE float envLuminance(vec3 rgb) { return dot(rgb, vec3(0.2126f, 0.7152f, 0.0722f)); }

// cos(theta) at the top edge of row j of h rows (row h: the bottom edge of the last).
TP_INLINE float envRowEdgeCos(uint j, uint h) { return cos(kPi * float(j) / float(h)); }

// Solid angle of one texel of row j.
TP_INLINE float envTexelSolidAngle(uint j, uint w, uint h) {
  return 2.0f * kPi / float(w) * (envRowEdgeCos(j, h) - envRowEdgeCos(j + 1u, h));
}

// The direction at fractions f (u, cos theta) across texel (i, j).
TP_INLINE vec3 envTexelDirection(uvec2 texel, vec2 f, uvec2 size) {
  float u = (float(texel.x) + f.x) / float(size.x);
  float cosTheta = mix(envRowEdgeCos(texel.y, size.y), envRowEdgeCos(texel.y + 1u, size.y), f.y);
  return equirectToDirectionCos(u, cosTheta);
}

// The texel holding unit direction d (the sampler's piecewise-constant environment).
TP_INLINE uvec2 envTexelOf(vec3 d, uvec2 size) {
  vec2 uv = directionToEquirect(d);
  return uvec2(min(ivec2(uv * vec2(size)), ivec2(size) - 1));
}

// The change of variables from the density of (u, v) on the unit square to
// the density per steradian: d omega = 2 pi^2 sin(theta) du dv.
TP_INLINE float envSolidAnglePdf(float pdfUv, float sinTheta) { return pdfUv / (2.0f * kPi * kPi * sinTheta); }

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::EnvParams) == 32);
#endif

#endif
