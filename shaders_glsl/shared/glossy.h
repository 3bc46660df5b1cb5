// The glossy lobe of the pool walls and the spheres, and the prefiltered
// environment that lights it, compiled both as GLSL and as C++: the raster
// passes, the prefilter (glossy_prefilter.comp), the CPU quadrature
// (render/glossy_quadrature) and the reference tracer share it.
//
// A glossy surface leaves (1 - s) of the Lambertian radiance and adds s G(r):
// the sky convolved with the normalised Phong lobe (e + 1) / 2pi max(0, r.w)^e
// about the mirror direction r, which integrates to 1 over the sphere, so a
// constant sky L gives G = L. A glossy sphere reflects its probe, the
// scene around it seen from its centre, and the walls above the water the
// pool's probe (render/glossy_probes); the walls under the water the sky.
// The lobe is not clipped by the surface, and there is no Fresnel factor.
//
// The prefiltered map is an equirectangular mip chain: level k, W_k = W_0 / 2^k
// texels wide, holds G for the exponent whose lobe is kGlossyTexelsPerLobe of
// its texels wide (e_k = (W_k / (2pi c))^2, sigma = 1 / sqrt(e) radians), so
// every level resolves its lobe; the lod of any other exponent follows from
// the same relation, and textureLod blends the two levels around it.
#ifndef TP_SHARED_GLOSSY_H
#define TP_SHARED_GLOSSY_H
#include "shared/constants.h"
#include "shared/equirect.h"
#include "shared/interop.h"

TP_BEGIN

// The lobe's angular width (1 / sqrt(e)) in texels of the level that holds it.
const float kGlossyTexelsPerLobe = 2.0f;
// The coarsest level's width: its exponent, (16 / 4pi)^2 = 1.6, is about a
// cosine lobe's; roughness 1 (e = 1) reads it.
const uint kGlossyMinWidth = 16u;
// The finest level's width at most (512: e_0 = 1660, a lobe of 1.4 degrees).
const uint kGlossyMaxWidth = 512u;
// How far over the water a probe's eye stands when its sphere's centre is
// under it (glossyProbeEye), in metres: over the flat water at its rest level.
const float kGlossyProbeLift = 1e-3f;
// Roughness is clamped to this before it becomes an exponent (2 / r^4 - 1
// would be infinite at 0); any roughness below the finest level's reads level 0.
const float kGlossyMinRoughness = 0.01f;

// The push constants of glossy_prefilter.comp, one dispatch per level.
struct GlossyParams {
  uvec4 size;     // x, y: the environment's width and height; z, w: this level's
  uvec4 samples;  // x: drawn from the environment, y: drawn from the lobe; z: the level
  vec4 lobe;      // x: the level's exponent
};

// The push constants of glossy_probe.comp, one dispatch per glossy sphere.
struct GlossyProbeParams {
  vec4 center;  // xyz: the sphere's centre, where its probe looks out from
};

// Where a glossy sphere's probe looks out from: its centre or, for a sphere
// through the water's rest level waterY with its centre under it, just
// above the water, so that the half in the air, the half a camera over the
// water sees, reflects what is over the water (from under it the sky comes
// through Snell's window). Without water, waterY is below everything.
TP_INLINE vec3 glossyProbeEye(vec3 center, float radius, float waterY) {
  if (center.y < waterY && center.y + radius > waterY) return vec3(center.x, waterY + kGlossyProbeLift, center.z);
  return center;
}

// The direction from a glossy sphere's probe's eye (glossyProbeEye) in which
// the probe holds what the mirror ray from p on its surface along unit r
// meets: where r goes up, r (the sky and what stands over the ground are
// far, seen alike from the eye); where it goes down, the direction to where it meets the ground's
// plane at groundY or, through the pool's opening (holeHalf, 0 for none),
// the water's rest level at waterY. Under the water, r.
TP_INLINE vec3 glossyProbeDirection(vec3 center, vec3 p, vec3 r, float groundY, float holeHalf, float waterY) {
  if (r.y >= 0.0f || (holeHalf > 0.0f && p.y <= waterY)) return r;
  float plane = groundY;
  if (p.y <= groundY) {
    plane = waterY;
  } else {
    vec3 q = p + ((groundY - p.y) / r.y) * r;
    if (max(abs(q.x), abs(q.z)) < holeHalf) plane = waterY;
  }
  return normalize(p + ((plane - p.y) / r.y) * r - center);
}

// Where the pool's probe looks out from: the pool's centre, halfway between
// the water's rest level and the rim, among the walls above the water.
TP_INLINE vec3 poolProbeCenter(float waterY, float rimY) { return vec3(0.0f, 0.5f * (waterY + rimY), 0.0f); }

// The direction from the pool's probe at `center` in which it holds what the
// mirror ray from p on a wall above the water along unit r meets: a wall
// across the pool (|x| or |z| at holeHalf) or the water at its rest level
// waterY; r where the ray leaves over the rim at rimY (the sky and the
// ground beyond are far, seen alike from the centre).
TP_INLINE vec3 poolProbeDirection(vec3 center, vec3 p, vec3 r, float holeHalf, float waterY, float rimY) {
  float s = 1e30f;
  if (abs(r.x) > 1e-6f) s = min(s, (sign(r.x) * holeHalf - p.x) / r.x);
  if (abs(r.z) > 1e-6f) s = min(s, (sign(r.z) * holeHalf - p.z) / r.z);
  if (r.y < 0.0f) s = min(s, (waterY - p.y) / r.y);
  vec3 q = p + s * r;
  if (s <= 0.0f || q.y > rimY) return r;
  return normalize(q - center);
}

// The Phong exponent of a roughness in [0, 1]: e = 2 / r^4 - 1 (1, a cosine
// lobe, at roughness 1; the Beckmann-Phong correspondence with alpha = r^2,
// shifted by 1 so that the lobe stays continuous at its horizon).
TP_INLINE float glossyExponent(float roughness) {
  float r = max(roughness, kGlossyMinRoughness);
  return 2.0f / (r * r * r * r) - 1.0f;
}

// The exponent level k of a map `baseWidth` texels wide holds.
TP_INLINE float glossyLevelExponent(uint baseWidth, uint level) {
  float w = float(baseWidth >> level) / (2.0f * kPi * kGlossyTexelsPerLobe);
  return w * w;
}

// The (fractional) level of exponent e; the caller clamps it to the chain.
TP_INLINE float glossyLod(float exponent, uint baseWidth) {
  return log2(float(baseWidth) / (2.0f * kPi * kGlossyTexelsPerLobe)) - 0.5f * log2(max(exponent, 1e-6f));
}

// The normalised lobe about r at a direction whose cosine to r is cosAngle:
// also the density per steradian of glossyLobeDirection's directions.
TP_INLINE float glossyLobe(float exponent, float cosAngle) {
  return (exponent + 1.0f) / (2.0f * kPi) * pow(max(cosAngle, 0.0f), exponent);
}

// A direction drawn from the lobe about unit r for a point xi of the unit
// square: cos = xi.x^(1 / (e + 1)) about r, the azimuth 2pi xi.y.
TP_INLINE vec3 glossyLobeDirection(vec3 r, float exponent, vec2 xi) {
  float cosAngle = pow(max(xi.x, 1e-30f), 1.0f / (exponent + 1.0f));
  float sinAngle = sqrt(max(1.0f - cosAngle * cosAngle, 0.0f));
  float phi = 2.0f * kPi * xi.y;
  vec3 helper = abs(r.y) < 0.999f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
  vec3 t = normalize(cross(helper, r));
  vec3 b = cross(r, t);
  return normalize(sinAngle * cos(phi) * t + sinAngle * sin(phi) * b + cosAngle * r);
}

// The surface's radiance from its Lambertian part and the glossy lobe's
// G (material.x: specular s, the lobe's share); without gloss, the
// Lambertian radiance untouched.
TP_INLINE vec3 glossyMix(vec3 diffuse, vec3 glossy, float specular) {
  return specular > 0.0f ? (1.0f - specular) * diffuse + specular * glossy : diffuse;
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::GlossyParams) == 48);
static_assert(sizeof(tp::shader::GlossyProbeParams) == 16);
#endif

#endif
