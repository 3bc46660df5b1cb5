#version 450
#extension GL_GOOGLE_include_directive : require
// Lambertian checkered ground lit by the sun and the sky. The checker is box
// filtered over the pixel footprint so that it does not alias at the horizon.
#include "shared/frame.h"
#include "shared/ground.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { GroundParams ground; };

const float PI = 3.14159265358979323846;

// Integral from 0 to x of the square wave that is +1 on [0,1) and -1 on [1,2), period 2.
vec2 squareWaveIntegral(vec2 x) {
  vec2 f = fract(x * 0.5);
  return 2.0 * (f - 2.0 * max(f - 0.5, 0.0));
}

// Fraction of the pixel footprint [p - w/2, p + w/2]^2 on odd squares (0..1):
// the box filter is separable, so the mean of the product of the two square
// waves is the product of their means.
float filteredChecker(vec2 p, vec2 w) {
  w = max(w, vec2(1e-6));
  vec2 wave = (squareWaveIntegral(p + 0.5 * w) - squareWaveIntegral(p - 0.5 * w)) / w;
  return 0.5 - 0.5 * wave.x * wave.y;
}

void main() {
  vec2 p = worldPosition.xz / ground.plane.z;
  float odd = filteredChecker(p, fwidth(p));
  vec3 albedo = mix(ground.albedoA.rgb, ground.albedoB.rgb, odd);
  vec3 n = vec3(0.0, 1.0, 0.0);
  vec3 irradiance = frame.sunIrradiance.rgb * max(dot(n, frame.sunDirection.xyz), 0.0) + frame.skyIrradiance.rgb;
  color = vec4(albedo / PI * irradiance, 1.0);
}
