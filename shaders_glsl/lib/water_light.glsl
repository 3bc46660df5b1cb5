// The water surface seen from above in the accurate mode: its reflection,
// its refraction cast against the pool and the objects, mixed by Schlick's
// Fresnel. Shared by the forward fragment shader (water_surface.frag) and
// the deferred pass that shades each pixel once (water_surface_deferred.comp),
// so both give the same bits; with the surface's push constants.
#ifndef TP_LIB_WATER_LIGHT
#define TP_LIB_WATER_LIGHT
#include "lib/scene_rays.glsl"
#include "shared/water_surface.h"
layout(push_constant) uniform Push { WaterSurfaceParams surface; };

// Schlick's Fresnel reflectance, from the cosine of the angle on the air side.
float waterFresnel(float cosAir) {
  const float ior = surface.extinction.w;
  const float f0 = ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  return f0 + (1.0 - f0) * pow(1.0 - clamp(cosAir, 0.0, 1.0), 5.0);
}

// Radiance crossing the surface is scaled by the squared ratio of the
// indices (L / n^2 is conserved along a ray): light from under the water
// seen from the air keeps 1 / n^2 of it (besides Fresnel's loss), light from
// the air seen from under the water gains n^2 (Snell's window is brighter).
float waterRadianceGain() { return surface.extinction.w * surface.extinction.w; }

// The light leaving the surface at `position` towards the camera, seen as
// `v` says; rd the differentials of the refracted ray (of position and
// normalize(v.refracted)).
vec3 seenFromAbove(vec3 position, ViewFromAbove v, RayDifferential rd) {
  const vec3 reflected = radianceAbove(position, reflect(v.view, v.normal));
  vec3 transmitted = vec3(0.0);
  const vec3 t = v.refracted;
  if (dot(t, t) > 0.0 && t.y < 0.0) transmitted = radianceBelow(position, normalize(t), rd) / waterRadianceGain();
  return mix(transmitted, reflected, waterFresnel(-dot(v.view, v.normal)));
}

#endif
