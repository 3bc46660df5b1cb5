// The procedural HDR sky: parameters (push constants of sky.comp) and the
// radiance function, compiled both as GLSL and as C++ (the CPU uses it to
// integrate the sky's irradiance and to check the GPU's sky texture).
#ifndef TP_SHARED_SKY_H
#define TP_SHARED_SKY_H
#include "shared/interop.h"
#include "shared/noise.h"
#include "shared/constants.h"

TP_BEGIN

// 128 bytes, the most push constants lavapipe (and the Vulkan minimum) allows:
// the clouds' settings fill the w lanes the sky left unused.
struct SkyParams {
  vec4 zenith;        // rgb radiance straight up; w: exponent of the horizon-to-zenith blend
  vec4 horizon;       // rgb radiance at the horizon; w: width (in sin of elevation) of the horizon-to-ground blend
  vec4 ground;        // rgb radiance below the horizon; w: the clouds' noise frequency on their plane
  vec4 sunDirection;  // xyz unit vector towards the sun; w: cosine of the sun's angular radius
  vec4 sunRadiance;   // rgb radiance of the sun disk; w: the clouds' noise persistence
  vec4 glow;          // rgb radiance of the glow around the sun; w: its exponent in cos(angle to sun)
  vec4 cloudColor;    // rgb radiance of a cloud; w: coverage (0: none, 1: overcast)
  uvec4 counts;       // x: equirectangular texture width (the height is half); the clouds' y: noise kind (TP_NOISE_*), z: seed, w: octaves
};

// The width, in noise density, of a cloud's edge, from clear sky to all cloud.
const float kCloudEdgeSoftness = 0.2f;
// Clouds fade in from the horizon up to this sin of elevation: the plane they
// lie on runs out to infinity there, and its noise to aliasing.
const float kCloudHorizonFade = 0.1f;

// The clouds' density along unit direction d (d.y > 0), in [0, 1]: the
// fractal sum of noise on the plane y = 1 above the eye where d meets it,
// band-limited to the sky texture. One texel spans 2 pi / width radians, and
// on the plane 1 / d.y^2 times that along the elevation (the faster way), so
// an octave of frequency f has c = f 2 pi / (width d.y^2) cycles per texel: it
// counts in full below 1/4 cycle, fades to its mean by 1/2 (the texture's
// Nyquist limit) and is left out beyond, so that the texture does not alias.
TP_INLINE float cloudDensity(SkyParams s, vec3 d) {
  vec2 onPlane = vec2(d.x, d.z) * (s.ground.w / d.y);
  float texelOnPlane = 2.0f * kPi / (float(s.counts.x) * d.y * d.y);
  bool signedKind = s.counts.y == TP_NOISE_GRADIENT || s.counts.y == TP_NOISE_SIMPLEX;
  float sum = 0.0f, total = 0.0f, amplitude = 1.0f, frequency = 1.0f;
  for (uint i = 0u; i < s.counts.w; ++i) {
    float weight = clamp(2.0f - 4.0f * s.ground.w * frequency * texelOnPlane, 0.0f, 1.0f);
    if (weight > 0.0f) {
      float n = noiseOfKind(s.counts.y, onPlane * frequency, s.counts.z + i);
      if (signedKind) n = 0.5f * n + 0.5f;
      sum += amplitude * weight * (n - 0.5f);
    }
    total += amplitude;
    amplitude *= s.sunRadiance.w;
    frequency *= 2.0f;
  }
  return 0.5f + sum / total;
}

// How much cloud (0..1) covers the sky along unit direction d (d.y > 0): the
// density pushed over a threshold by the coverage, fading out towards the
// horizon. Coverage 0 leaves every density (<= 1) clear, coverage 1 covers
// every density (>= 0).
TP_INLINE float cloudAmount(SkyParams s, vec3 d) {
  float coverage = s.cloudColor.w;
  float amount = smoothstep(0.0f, 1.0f, (cloudDensity(s, d) - 1.0f + coverage * (1.0f + kCloudEdgeSoftness)) / kCloudEdgeSoftness);
  return amount * smoothstep(0.0f, kCloudHorizonFade, d.y);
}

// Radiance of the sky seen along unit direction d, without (withSun = 0) or
// with the sun disk; clouds hide the sky and its glow, not the sun disk.
TP_INLINE vec3 skyRadiance(SkyParams s, vec3 d, float withSun) {
  float up = d.y;
  vec3 sky = mix(vec3(s.horizon), vec3(s.zenith), pow(max(up, 0.0f), s.zenith.w));
  float cosSun = dot(d, vec3(s.sunDirection));
  sky += vec3(s.glow) * pow(max(cosSun, 0.0f), s.glow.w);
  if (s.cloudColor.w > 0.0f && up > 0.0f) sky = mix(sky, vec3(s.cloudColor), cloudAmount(s, d));
  if (withSun > 0.0f && cosSun >= s.sunDirection.w) sky += vec3(s.sunRadiance);
  float aboveHorizon = smoothstep(-s.horizon.w, 0.0f, up);
  return mix(vec3(s.ground), sky, aboveHorizon);
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SkyParams) == 128);
#endif

#endif
