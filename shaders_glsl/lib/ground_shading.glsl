// The checkered Lambertian ground, shared by the ground pass and by rays
// refracted through the water onto it.
#ifndef TP_LIB_GROUND_SHADING
#define TP_LIB_GROUND_SHADING
#include "shared/frame.h"
#include "shared/ground.h"

const float GROUND_PI = 3.14159265358979323846;

// Integral from 0 to x of the square wave that is +1 on [0,1) and -1 on [1,2), period 2.
vec2 squareWaveIntegral(vec2 x) {
  vec2 f = fract(x * 0.5);
  return 2.0 * (f - 2.0 * max(f - 0.5, 0.0));
}

// Fraction of the footprint [p - w/2, p + w/2]^2 on odd squares (0..1): the box
// filter is separable, so the mean of the product of the two square waves is
// the product of their means. Filtering keeps the checker from aliasing.
float filteredChecker(vec2 p, vec2 w) {
  w = max(w, vec2(1e-6));
  vec2 wave = (squareWaveIntegral(p + 0.5 * w) - squareWaveIntegral(p - 0.5 * w)) / w;
  return 0.5 - 0.5 * wave.x * wave.y;
}

// Radiance leaving the ground at world xz (pixel footprint in metres) with
// normal n, lit by the sun and by the sky's irradiance on an up-facing surface.
vec3 groundRadiance(GroundParams ground, FrameUniforms frame, vec2 xz, vec2 footprint, vec3 n) {
  vec2 p = xz / ground.plane.z;
  float odd = filteredChecker(p, footprint / ground.plane.z);
  vec3 albedo = mix(ground.albedoA.rgb, ground.albedoB.rgb, odd);
  vec3 irradiance = frame.sunIrradiance.rgb * max(dot(n, frame.sunDirection.xyz), 0.0) + frame.skyIrradiance.rgb;
  return albedo / GROUND_PI * irradiance;
}

#endif
