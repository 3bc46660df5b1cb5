// The local shading of every surface (Lambertian, lit by the sun without
// shadows and by the sky's irradiance) and the
// cast of the water's refracted rays against the pool,
// compiled both as GLSL and as C++: the raster passes and the CPU reference (render/reference_*) shade
// with the same functions, so that their difference measures only the paths
// the light takes.
#ifndef TP_SHARED_SHADING_H
#define TP_SHARED_SHADING_H
#include "shared/constants.h"
#include "shared/equirect.h"
#include "shared/frame.h"
#include "shared/glass.h"
#include "shared/ground.h"
#include "shared/interop.h"
#include "shared/pool.h"
#include "shared/surface_pattern.h"
#include "shared/water_surface.h"

TP_BEGIN

// The sun's irradiance on a surface with normal n in the air, `sunShare` of
// it (the share of its disc in view, sunVisibility, times the caustics
// under the water).
// And with the sky's: the sky above the horizon seen from the normal
// (pi L (1 + n.y) / 2 for a uniform sky L).
TP_INLINE vec3 sunIrradianceOn(FrameUniforms frame, vec3 n, float sunShare) {
  return sunShare * vec3(frame.sunIrradiance) * max(dot(n, vec3(frame.sunDirection)), 0.0f);
}

TP_INLINE vec3 openAirIrradiance(FrameUniforms frame, vec3 n, float sunShare) {
  return sunIrradianceOn(frame, n, sunShare) + skyIrradiance(frame.skyIrradiance, n);
}

TP_INLINE vec3 lambertRadiance(FrameUniforms frame, vec3 albedo, vec3 n, float sunShare) {
  return albedo / kPi * openAirIrradiance(frame, n, sunShare);
}

// Radiance leaving the ground (or the pool's floor: its tiles) at world xz
// (pixel footprint in metres) with normal n, lit as lambertRadiance says.
TP_INLINE vec3 groundRadiance(GroundParams ground, FrameUniforms frame, vec2 xz, vec2 footprint, vec3 n, float sunScale) {
  return lambertRadiance(frame, groundAlbedo(ground, xz, footprint), n, sunScale);
}

// The finite-difference step of the floor's normals, in metres: well below the
// finest octave's lattice spacing, well above float round-off of the heights.
const float kPoolFloorNormalSpacing = 0.01f;

// Floor normal from central differences of the height function; `spacing` is
// the finite-difference step in metres.
TP_INLINE vec3 poolFloorNormal(PoolParams pool, vec2 xz, float spacing) {
  float dx = poolFloorHeight(pool, xz + vec2(spacing, 0.0f)) - poolFloorHeight(pool, xz - vec2(spacing, 0.0f));
  float dz = poolFloorHeight(pool, xz + vec2(0.0f, spacing)) - poolFloorHeight(pool, xz - vec2(0.0f, spacing));
  return normalize(vec3(-dx, 2.0f * spacing, -dz));
}

// Whether p lies in the pool under the water's rest level: lit through
// the surface, as flat water at that level passes the light.
TP_INLINE bool underRestLevel(PoolParams pool, vec3 p) { return pool.water.w > 0.0f && p.y < pool.water.x; }

// What the water takes from a beam of light on its way down to what it
// lights: its absorption, and of its scattering the share that leaves the
// beam's direction, 1 - g (the similarity relation: Henyey-Greenstein's
// forward share g goes on with the beam). With the whole extinction the
// floor in the sun under scattering water was darker than the path-traced
// truth's (docs/light-in-the-water.md). 0 scattering: the absorption.
TP_INLINE vec3 beamExtinction(PoolParams pool) {
  return vec3(pool.extinction) - pool.scattering.w * vec3(pool.scattering);
}

// The sun's irradiance on normal n at p under flat water: its disc's light
// refracted at the rest level, Fresnel's transmission taken, its solid angle
// compressed by cos(air) / cos(water) (the radiance's n^2 and the solid
// angle's 1 / n^2 cancel), absorbed over the slant path down.
TP_INLINE vec3 sunThroughFlatWater(PoolParams pool, FrameUniforms frame, vec3 p, vec3 n) {
  vec3 toSun = vec3(frame.sunDirection);
  if (toSun.y <= 0.0f) return vec3(0.0f);
  float ior = pool.water.y;
  vec3 travel = refract(-toSun, vec3(0.0f, 1.0f, 0.0f), 1.0f / ior);
  float cosWater = -travel.y;
  float depth = max(pool.water.x - p.y, 0.0f);
  float transmitted = 1.0f - fresnelDielectric(toSun.y, 1.0f, ior);
  return vec3(frame.sunIrradiance) * (transmitted * toSun.y / cosWater * max(dot(n, -travel), 0.0f)) *
         exp(-beamExtinction(pool) * (depth / cosWater));
}

// The direction the caustics texture's light lines run in: the sun's,
// refracted by flat water (downwards).
TP_INLINE vec3 causticsLight(PoolParams pool, vec3 toSun) {
  return refract(-toSun, vec3(0.0f, 1.0f, 0.0f), 1.0f / pool.water.y);
}

// The light line through world point p under the water: the xz where the
// flat water's refracted sun line through p crosses the rest level. The
// caustics texture is indexed by it over the pool's square, so the floor,
// the walls and the objects under the water read the light that reaches
// them from one texture: under flat water each line carries its own light.
TP_INLINE vec2 causticsLine(PoolParams pool, vec3 toSun, vec3 p) {
  vec3 f = causticsLight(pool, toSun);
  return vec2(p.x, p.z) + vec2(f.x, f.z) * ((pool.water.x - p.y) / min(f.y, -1e-6f));
}

// Where the caustics texture holds the light reaching world point p: its
// light line, kept within the lines the texture holds whole (pool.water.z).
TP_INLINE vec2 causticsUv(PoolParams pool, vec3 toSun, vec3 p) {
  vec2 line = clamp(causticsLine(pool, toSun, p), vec2(-pool.water.z), vec2(pool.water.z));
  return line / (2.0f * pool.box.x) + 0.5f;
}

// Distances along origin + s dir from inside the pool's square to the wall
// planes it goes towards: x to the x = +-half size pair, y to the z pair
// (1e30 when dir is parallel to them).
TP_INLINE vec2 poolWallDistances(PoolParams pool, vec3 origin, vec3 dir) {
  const float halfSize = pool.box.x;
  float sx = dir.x > 0.0f ? (halfSize - origin.x) / dir.x : (dir.x < 0.0f ? (-halfSize - origin.x) / dir.x : 1e30f);
  float sz = dir.z > 0.0f ? (halfSize - origin.z) / dir.z : (dir.z < 0.0f ? (-halfSize - origin.z) / dir.z : 1e30f);
  return vec2(sx, sz);
}

// The inward normal of the wall met first, given poolWallDistances.
TP_INLINE vec3 poolWallNormal(vec2 walls, vec3 dir) {
  return walls.x < walls.y ? vec3(-sign(dir.x), 0.0f, 0.0f) : vec3(0.0f, 0.0f, -sign(dir.z));
}

struct PoolHit {
  float distance;
  vec3 position;
  vec3 normal;
  bool floor;
};

TP_INLINE PoolHit poolHit(float distance, vec3 position, vec3 normal, bool onFloor) {
  PoolHit h;
  h.distance = distance;
  h.position = position;
  h.normal = normal;
  h.floor = onFloor;
  return h;
}

// Where world point p lands on the screen, in pixels from the top-left corner.
TP_INLINE vec2 screenPixel(FrameUniforms frame, vec3 p) {
  vec4 clip = frame.viewProjection * vec4(p, 1.0f);
  return (vec2(clip.x, clip.y) / clip.w * 0.5f + 0.5f) * vec2(frame.viewport.x, frame.viewport.y);
}

// The apparent-depth mode's guess (the original course project's): the
// refracted ray t from surface point p followed down to the pool's mean floor
// depth only. Its length:
TP_INLINE float apparentDepthDistance(PoolParams pool, vec3 p, vec3 t) {
  return max(p.y - (pool.box.y - pool.box.z), 0.0f) / -t.y;
}

// ... and the texel of the frame's own image it reads there (integer-valued).
TP_INLINE vec2 apparentDepthTexel(PoolParams pool, FrameUniforms frame, vec3 p, vec3 t) {
  vec2 pixel = screenPixel(frame, p + apparentDepthDistance(pool, p, t) * t);
  return clamp(floor(pixel), vec2(0.0f), vec2(frame.viewport.x, frame.viewport.y) - 1.0f);
}

// What reaches the camera from p along the straight path through the medium
// around it (the water when the camera is under the surface).
TP_INLINE vec3 viewTransmittance(CameraMedium medium, vec3 camera, vec3 p) {
  return exp(-vec3(medium.extinction) * distance(camera, p));
}

TP_END

#endif
