// The water surface's shading shared by its two refraction modes: inputs,
// bindings 0-4 and 6-8, what a ray leaving the surface sees above it (the
// spheres and boxes, the walls above the water, else the sky's
// equirectangular lookup) and below it (the pool and the objects, cast
// exactly, through the absorbing water), and Schlick's Fresnel.
#ifndef TP_LIB_WATER_SHADING
#define TP_LIB_WATER_SHADING
#include "shared/shading.h"
#include "shared/objects.h"
#include "shared/water_surface.h"
#include "lib/glossy_lookup.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform sampler2D skyTexture;
layout(binding = 3) uniform Pool { PoolParams pool; };
layout(binding = 4) uniform Objects { SceneObjects objects; };  // shared/object_cast.h's
layout(binding = 6) uniform sampler2D caustics;
layout(binding = 7) uniform sampler2D glossyMap;  // the glossy walls' and spheres' environment
layout(binding = 8) readonly buffer FloorVertices { vec4 floorVertices[]; };  // shared/pool_trace.h's
#include "shared/pool_trace.h"
#include "shared/object_cast.h"
layout(push_constant) uniform Push { WaterSurfaceParams surface; };

vec3 sky(vec3 direction) { return texture(skyTexture, directionToEquirect(direction)).rgb; }

// What the water scatters into the ray from `start` along `dir` (unit, under
// the water) over `length`; nothing, and no code, in the variants for water
// that does not scatter.
#ifdef TP_SCATTERING
vec3 inScatter(vec3 start, vec3 dir, float length) {
  return waterInScatter(surface.extinction.rgb, surface.scattering, surface.placement.y, surface.extinction.w,
                        surface.grid.y, start, dir, length);
}
#else
vec3 inScatter(vec3 start, vec3 dir, float length) { return vec3(0.0); }
#endif

// What a ray leaving the surface at p (inside the pool, below the rim) upwards
// sees: an object, the part of a wall above the water, or the sky over the rim.
vec3 radianceAbove(vec3 p, vec3 r) {
  const vec2 walls = poolWallDistances(pool, p, r);
  const float sWall = min(walls.x, walls.y);
  const bool wall = sWall > 0.0 && p.y + sWall * r.y <= pool.box.y;  // below the rim
  const ObjectHit object = castObjects(objects.count.xy, p, r, wall ? sWall : 1e30);
  if (object.distance <= 0.0 && !wall) return sky(r);
  // One sun share for what is met (the shader holds its code once).
  const float distance = object.distance > 0.0 ? object.distance : sWall;
  const float sunShare = frameSunShare(p + distance * r);
  if (object.distance > 0.0) {
    return glossyRadiance(glossyMap, objectRadiance(frame, object.albedo, object.normal, sunShare), r, object.normal,
                          object.material);
  }
  // The wall's bricks point-sampled, as the reference tracer does: derivatives
  // are not to be had in this divergent branch.
  const vec3 wallNormal = poolWallNormal(walls, r);
  return glossyRadiance(glossyMap, poolWallRadiance(pool, frame, p + sWall * r, wallNormal, vec2(0.0), sunShare), r,
                        wallNormal, pool.wallGloss.xy);
}

// A ray's screen derivatives (Igehy 1999): of its origin and of its unit
// direction, one pixel right (x) and down (y).
struct RayDifferential {
  vec3 originX, originY, directionX, directionY;
};

// Taken where every lane of the pixel quad runs the same code: derivatives
// of values computed in divergent code (a cast's hit) are undefined. Scaled
// to the filter's width (FrameUniforms::sampling).
RayDifferential rayDifferential(vec3 origin, vec3 direction) {
  const float w = frame.sampling.x;
  return RayDifferential(w * dFdx(origin), w * dFdy(origin), w * dFdx(direction), w * dFdy(direction));
}

// The footprint in xz of the pixel where its ray, origin + s dir, meets a
// surface with normal n: each differential carried along the ray to the
// surface's tangent plane.
vec2 hitFootprint(RayDifferential rd, vec3 dir, float s, vec3 n) {
  const vec3 x = rd.originX + s * rd.directionX, y = rd.originY + s * rd.directionY;
  const float facing = dot(dir, n);
  const vec3 dx = x - dir * (dot(x, n) / facing), dy = y - dir * (dot(y, n) / facing);
  return abs(dx.xz) + abs(dy.xz);
}

// What a ray leaving the surface at p downwards sees: the pool (walls, and the
// floor lit through the caustics) or an object in front of it, attenuated
// along its path through the water.
vec3 radianceBelow(vec3 p, vec3 t, RayDifferential rd) {
  const PoolHit hit = tracePool(pool, p, t);
  const ObjectHit object = castObjects(objects.count.zw, p, t, hit.distance);
  const float distance = object.distance > 0.0 ? object.distance : hit.distance;
  // One sun share for what is met (the shader holds its code once), through
  // the waves (the caustics texture at its light line).
  const vec3 met = p + distance * t;
  const float sunShare = frameSunShare(met) * texture(caustics, causticsUv(pool, frame.sunDirection.xyz, met)).r;
  vec3 radiance;
  if (object.distance > 0.0) {
    radiance = glossyRadiance(glossyMap, objectRadiance(frame, object.albedo, object.normal, sunShare), t,
                              object.normal, object.material);
  } else if (hit.floor) {
    radiance = poolFloorRadiance(pool, frame, hit.position, hit.normal, hitFootprint(rd, t, hit.distance, hit.normal),
                                 sunShare);
  } else {
    radiance = glossyRadiance(glossyMap, poolWallRadiance(pool, frame, hit.position, hit.normal, vec2(0.0), sunShare), t,
                              hit.normal, pool.wallGloss.xy);
  }
  return radiance * exp(-surface.extinction.rgb * distance) + inScatter(p, t, distance);
}

// Schlick's Fresnel reflectance, from the cosine of the angle on the air side.
float waterFresnel(float cosAir) {
  const float ior = surface.extinction.w;
  const float f0 = ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  return f0 + (1.0 - f0) * pow(1.0 - clamp(cosAir, 0.0, 1.0), 5.0);
}

// The surface seen from under the water (the back of the mesh, whose front
// faces the sky): reflected light from below, the refracted ray to the air
// (none past the critical angle: total internal reflection), and the water
// between the surface and the camera.
vec4 shadeFromBelow(vec3 view, vec3 n) {
  n = -n;  // towards the camera, into the water
  const vec3 r = reflect(view, n);
  const vec3 reflected = radianceBelow(worldPosition, r, rayDifferential(worldPosition, r));
  const vec3 t = refract(view, n, surface.extinction.w);
  const bool total = dot(t, t) == 0.0;
  const vec3 transmitted = total ? vec3(0.0) : radianceAbove(worldPosition, t);
  const float fresnel = total ? 1.0 : waterFresnel(-dot(t, n));
  const float toCamera = distance(frame.cameraPosition.xyz, worldPosition);
  const vec3 camera = frame.cameraPosition.xyz;
  return vec4(mix(transmitted, reflected, fresnel) * exp(-surface.extinction.rgb * toCamera) +
                  inScatter(camera, (worldPosition - camera) / toCamera, toCamera),
              1.0);
}

#endif
