// The glossy lobe's light as the raster passes read it: the prefiltered
// environment (glossy_prefilter.comp, shared/glossy.h) at the lod of the
// surface's exponent, textureLod blending the two levels around it
// (roughness past either end of the chain reads its first or last level).
// The reference tracer computes the same G exactly (render/glossy_quadrature).
#ifndef TP_LIB_GLOSSY_LOOKUP
#define TP_LIB_GLOSSY_LOOKUP
#include "shared/glossy.h"
#include "shared/pool.h"
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

// The same for a sphere (xyz centre, w radius) reading its probe
// (render/glossy_probes) at p: the direction from the probe's eye to where
// the mirror ray meets the ground or the water (glossyProbeDirection).
vec3 glossyProbeRadiance(sampler2D probe, PoolParams pool, vec4 sphere, vec3 p, vec3 diffuse, vec3 incoming, vec3 n,
                         vec2 material) {
  if (!kGlossySurfaces || material.x <= 0.0) return diffuse;
  const float waterY = pool.box.x > 0.0 ? pool.water.x : -1e30;  // no pool: no water
  const vec3 r = glossyProbeDirection(glossyProbeEye(sphere.xyz, sphere.w, waterY), p, reflect(incoming, n),
                                      pool.ground.plane.y, pool.ground.plane.w, pool.water.x);
  return glossyMix(diffuse, glossyEnvironment(probe, r, material.y), material.x);
}

// The same for a pool wall at p: above the water the pool's probe, in the
// direction from its centre to what the mirror ray meets across the pool
// (poolProbeDirection); under the water the sky's map.
vec3 glossyWallRadiance(sampler2D probe, sampler2D sky, PoolParams pool, vec3 p, vec3 diffuse, vec3 incoming, vec3 n,
                        vec2 material) {
  if (!kGlossySurfaces || material.x <= 0.0) return diffuse;
  const vec3 r = reflect(incoming, n);
  if (p.y <= pool.water.x) return glossyMix(diffuse, glossyEnvironment(sky, r, material.y), material.x);
  const vec3 toward =
      poolProbeDirection(poolProbeCenter(pool.water.x, pool.box.y), p, r, pool.box.x, pool.water.x, pool.box.y);
  return glossyMix(diffuse, glossyEnvironment(probe, toward, material.y), material.x);
}

#endif
