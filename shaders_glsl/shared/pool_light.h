// The light of the pool's floor and walls under the water, shared with C++:
// the sun through the surface computed per point (sunThroughFlatWater, with
// the caustics and shadows the caller brings), and everything else baked
// once per scene (shading/pool_light.hpp): the sky through Snell's window
// with Fresnel's transmission, the walls' occlusion and the absorption on
// the way down, the light the surface's underside reflects back (total
// internal reflection outside the window), and the pool's own bounces,
// the sun's among them. Flat water at its rest level and the pool without
// its objects: what stands still.
//
// The baked irradiance follows the floor's vertices in the same buffer
// (shared/pool_trace.h's `floorVertices`): the floor's grid of
// TP_POOL_LIGHT_FLOOR texels a side over the pool's square, then each wall's
// TP_POOL_LIGHT_ALONG by TP_POOL_LIGHT_DOWN texels from the rest level down
// to the floor's lowest vertex, walls in poolLightWall's order. Read
// bilinearly between texel centres, clamped at the edges.
#ifndef TP_SHARED_POOL_LIGHT_H
#define TP_SHARED_POOL_LIGHT_H
#include "shared/pool_trace.h"
#include "shared/shading.h"

#define TP_POOL_LIGHT_FLOOR 16
#define TP_POOL_LIGHT_ALONG 16
#define TP_POOL_LIGHT_DOWN 8
#define TP_POOL_LIGHT_TEXELS \
  (TP_POOL_LIGHT_FLOOR * TP_POOL_LIGHT_FLOOR + 4 * TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_DOWN)

TP_BEGIN

// The wall facing inward normal n: 0 at -x, 1 at +x, 2 at -z, 3 at +z.
TP_INLINE int poolLightWall(vec3 n) {
  if (abs(n.x) > abs(n.z)) return n.x > 0.0f ? 0 : 1;
  return n.z > 0.0f ? 2 : 3;
}

// Where p lies on its wall's grid: along it (x for the z walls, z for the x
// walls) and down from the rest level to the floor's lowest vertex, 0..1.
TP_INLINE vec2 poolLightWallUv(PoolParams pool, vec3 p, int wall) {
  float along = wall < 2 ? p.z : p.x;
  return vec2((along + pool.box.x) / (2.0f * pool.box.x), (pool.water.x - p.y) / (pool.water.x - pool.terrain.z));
}

TP_INLINE vec3 poolLightTexel(PoolParams pool, int index TP_FLOOR_VERTICES_PARAM) {
  vec4 t = floorVertices[int(pool.noise.z * pool.noise.z) + index];
  return vec3(t.x, t.y, t.z);
}

// The grid of `width` x `height` texels from `first`, row by row, at uv
// (0..1 over the grid's extent), bilinear between texel centres.
TP_INLINE vec3 poolLightGrid(PoolParams pool, int first, int width, int height, vec2 uv TP_FLOOR_VERTICES_PARAM) {
  vec2 g = clamp(vec2(uv.x * float(width), uv.y * float(height)) - 0.5f, vec2(0.0f),
                 vec2(float(width - 1), float(height - 1)));
  int i = min(int(floor(g.x)), width - 2), j = min(int(floor(g.y)), height - 2);
  vec2 f = g - vec2(float(i), float(j));
  int k = first + j * width + i;
  vec3 a = poolLightTexel(pool, k TP_FLOOR_VERTICES_ARG), b = poolLightTexel(pool, k + 1 TP_FLOOR_VERTICES_ARG);
  vec3 c = poolLightTexel(pool, k + width TP_FLOOR_VERTICES_ARG);
  vec3 d = poolLightTexel(pool, k + width + 1 TP_FLOOR_VERTICES_ARG);
  vec3 low = a + (b - a) * f.x, high = c + (d - c) * f.x;
  return low + (high - low) * f.y;
}

// The baked irradiance at p under the water, on the floor (n mostly up) or
// a wall.
TP_INLINE vec3 poolLightAt(PoolParams pool, vec3 p, vec3 n TP_FLOOR_VERTICES_PARAM) {
  if (n.y > 0.5f) {
    vec2 uv = (vec2(p.x, p.z) + pool.box.x) / (2.0f * pool.box.x);
    return poolLightGrid(pool, 0, TP_POOL_LIGHT_FLOOR, TP_POOL_LIGHT_FLOOR, uv TP_FLOOR_VERTICES_ARG);
  }
  int wall = poolLightWall(n);
  int first = TP_POOL_LIGHT_FLOOR * TP_POOL_LIGHT_FLOOR + wall * TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_DOWN;
  return poolLightGrid(pool, first, TP_POOL_LIGHT_ALONG, TP_POOL_LIGHT_DOWN, poolLightWallUv(pool, p, wall)
                       TP_FLOOR_VERTICES_ARG);
}

// The sun's and the sky's irradiance on a surface of the pool at p with
// normal n, `sunShare` of the sun's. Above the water the open sky's (SH9)
// and the sun's; under the rest level the sun through the flat surface and
// the baked light.
TP_INLINE vec3 poolIrradiance(PoolParams pool, FrameUniforms frame, vec3 p, vec3 n, float sunShare
                              TP_FLOOR_VERTICES_PARAM) {
  if (underRestLevel(pool, p))
    return sunShare * sunThroughFlatWater(pool, frame, p, n) + poolLightAt(pool, p, n TP_FLOOR_VERTICES_ARG);
  return openAirIrradiance(frame, n, sunShare);
}

// The floor, lit as poolIrradiance says. `caustic`: the sun's irradiance
// through the waves relative to flat water (the caustics texture; 1 where
// caustics are off), times its disc's share in view (sunVisibility).
TP_INLINE vec3 poolFloorRadiance(PoolParams pool, FrameUniforms frame, vec3 position, vec3 normal, vec2 footprint,
                                 float caustic TP_FLOOR_VERTICES_PARAM) {
  return groundAlbedo(pool.tiles, vec2(position.x, position.z), footprint) / kPi *
         poolIrradiance(pool, frame, position, normal, caustic TP_FLOOR_VERTICES_ARG);
}

// A wall, lit as poolIrradiance says; the pool's own rim is not counted
// above the water. `footprint`: the pixel's on the wall, in metres along
// and down it (0 point-samples the bricks). `sunShare`: the share of the
// sun's disc in view (sunVisibility).
TP_INLINE vec3 poolWallRadiance(PoolParams pool, FrameUniforms frame, vec3 position, vec3 normal, vec2 footprint,
                                float sunShare TP_FLOOR_VERTICES_PARAM) {
  return poolWallAlbedo(pool, poolWallCoordinates(pool, position, normal), footprint) / kPi *
         poolIrradiance(pool, frame, position, normal, sunShare TP_FLOOR_VERTICES_ARG);
}

TP_END

#endif
