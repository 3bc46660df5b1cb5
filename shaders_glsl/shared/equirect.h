// The equirectangular mapping of the sky texture (u = phi / 2pi + 1/2 with
// phi = atan(z, x), v = theta / pi with theta = acos(y), the original course
// project's convention), compiled both as GLSL and as C++: the sky pass, the
// shading, the reference tracer and the environment sampler share it.
#ifndef TP_SHARED_EQUIRECT_H
#define TP_SHARED_EQUIRECT_H
#include "shared/constants.h"
#include "shared/interop.h"

TP_BEGIN


TP_INLINE vec2 directionToEquirect(vec3 d) {
  return vec2(atan(d.z, d.x) / (2.0f * kPi) + 0.5f, acos(clamp(d.y, -1.0f, 1.0f)) / kPi);
}

TP_INLINE vec3 equirectToDirection(vec2 uv) {
  float phi = (uv.x - 0.5f) * 2.0f * kPi;
  float theta = uv.y * kPi;
  return vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}

// The direction at u with cos(theta) = cosTheta: the environment sampler
// draws cos(theta) uniformly within a texel's row (its solid angle is
// uniform in cos(theta)), so it needs no acos.
TP_INLINE vec3 equirectToDirectionCos(float u, float cosTheta) {
  float phi = (u - 0.5f) * 2.0f * kPi;
  float sinTheta = sqrt(max(1.0f - cosTheta * cosTheta, 0.0f));
  return vec3(sinTheta * cos(phi), cosTheta, sinTheta * sin(phi));
}

TP_END

#endif
