// The procedural HDR sky: parameters (push constants of sky.comp) and the
// radiance function, compiled both as GLSL and as C++ (the CPU uses it to
// integrate the sky's irradiance and to check the GPU's sky texture).
#ifndef TP_SHARED_SKY_H
#define TP_SHARED_SKY_H
#include "shared/interop.h"

TP_BEGIN

struct SkyParams {
  vec4 zenith;        // rgb radiance straight up; w: exponent of the horizon-to-zenith blend
  vec4 horizon;       // rgb radiance at the horizon; w: width (in sin of elevation) of the horizon-to-ground blend
  vec4 ground;        // rgb radiance below the horizon; w unused
  vec4 sunDirection;  // xyz unit vector towards the sun; w: cosine of the sun's angular radius
  vec4 sunRadiance;   // rgb radiance of the sun disk; w unused
  vec4 glow;          // rgb radiance of the glow around the sun; w: its exponent in cos(angle to sun)
  uvec4 size;         // equirectangular texture width, height; zw unused
};

// Radiance of the sky seen along unit direction d, without (withSun = 0) or with the sun disk.
TP_INLINE vec3 skyRadiance(SkyParams s, vec3 d, float withSun) {
  float up = d.y;
  vec3 sky = mix(vec3(s.horizon), vec3(s.zenith), pow(max(up, 0.0f), s.zenith.w));
  float cosSun = dot(d, vec3(s.sunDirection));
  sky += vec3(s.glow) * pow(max(cosSun, 0.0f), s.glow.w);
  if (withSun > 0.0f && cosSun >= s.sunDirection.w) sky += vec3(s.sunRadiance);
  float aboveHorizon = smoothstep(-s.horizon.w, 0.0f, up);
  return mix(vec3(s.ground), sky, aboveHorizon);
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SkyParams) == 112);
#endif

#endif
