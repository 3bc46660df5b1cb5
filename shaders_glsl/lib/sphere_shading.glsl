// Lambertian spheres: lit by the sun and by the sky's irradiance, scaled for
// the part of the sky a tilted surface sees (1/2 (1 + n.y)).
#ifndef TP_LIB_SPHERE_SHADING
#define TP_LIB_SPHERE_SHADING
#include "shared/frame.h"

vec3 sphereRadiance(FrameUniforms frame, vec3 albedo, vec3 n) {
  const float pi = 3.14159265358979323846;
  vec3 irradiance = frame.sunIrradiance.rgb * max(dot(n, frame.sunDirection.xyz), 0.0) +
                    0.5 * (1.0 + n.y) * frame.skyIrradiance.rgb;
  return albedo / pi * irradiance;
}

// Distance along origin + s dir (dir unit) to the sphere's front surface, or -1.
float raySphere(vec3 origin, vec3 dir, vec4 sphere) {
  vec3 oc = origin - sphere.xyz;
  float b = dot(oc, dir);
  float c = dot(oc, oc) - sphere.w * sphere.w;
  float discriminant = b * b - c;
  if (discriminant < 0.0) return -1.0;
  float s = -b - sqrt(discriminant);
  return s > 0.0 ? s : -1.0;
}

#endif
