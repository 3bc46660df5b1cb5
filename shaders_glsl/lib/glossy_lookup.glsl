// The glossy lobe's light as the raster passes read it: the prefiltered
// environment (glossy_prefilter.comp, shared/glossy.h) at the lod of the
// surface's exponent, textureLod blending the two levels around it
// (roughness past either end of the chain reads its first or last level).
// The reference tracer computes the same G exactly (render/glossy_quadrature).
#ifndef TP_LIB_GLOSSY_LOOKUP
#define TP_LIB_GLOSSY_LOOKUP
#include "shared/glossy.h"
#include "shared/specialization.h"

vec3 glossyEnvironment(sampler2D map, vec3 r, float roughness) {
  const uint base = uint(textureSize(map, 0).x);
  const float lod = clamp(glossyLod(glossyExponent(roughness), base), 0.0, float(textureQueryLevels(map) - 1));
  return textureLod(map, directionToEquirect(r), lod).rgb;
}

// A surface's radiance: its Lambertian `diffuse` and, with material.x
// (specular) > 0, the glossy lobe about the mirror direction of `incoming`
// (the ray arriving at it) in normal n, roughness material.y.
vec3 glossyRadiance(sampler2D map, vec3 diffuse, vec3 incoming, vec3 n, vec2 material) {
  if (!kGlossySurfaces || material.x <= 0.0) return diffuse;
  return glossyMix(diffuse, glossyEnvironment(map, reflect(incoming, n), material.y), material.x);
}

#endif
