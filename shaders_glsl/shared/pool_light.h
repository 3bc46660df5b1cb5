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
// to the floor's lowest vertex, walls in poolLightWall's order; then each
// wall's TP_POOL_LIGHT_ALONG by TP_POOL_LIGHT_UP texels above the water, from
// the rim down to the rest level (the dry band: it sees the water and the
// pool's other walls below its horizon, not the open ground the sky's SH9
// holds there). Read bilinearly between texel centres, clamped at the edges.
//
// Then the light around: the radiance arriving from every direction, in
// SH9 (9 vec4s a point, rgb), at the centres of a grid of cells over the
// pool's water, TP_POOL_AROUND_SIDE a side across its square and
// TP_POOL_AROUND_LAYERS from the rest level down to the floor's lowest
// vertex; x fastest, then z, then down. It lights the objects under the
// water and is what the water scatters (shared/water_scattering.h). Read
// trilinearly between the points, held at the outer ones. One point at the
// pool's centre held it before; in scenes/underwater.json the light's mean
// by the floor is a third less in a corner than in the middle
// (docs/pool-light.md).
#ifndef TP_SHARED_POOL_LIGHT_H
#define TP_SHARED_POOL_LIGHT_H
#include "shared/pool_trace.h"
#include "shared/sh9.h"
#include "shared/shading.h"

#define TP_POOL_LIGHT_FLOOR 16
#define TP_POOL_LIGHT_ALONG 16
#define TP_POOL_LIGHT_DOWN 8
#define TP_POOL_LIGHT_UP 4
// The first of the dry band's texels.
#define TP_POOL_LIGHT_DRY_START (TP_POOL_LIGHT_FLOOR * TP_POOL_LIGHT_FLOOR + 4 * TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_DOWN)
#define TP_POOL_LIGHT_TEXELS (TP_POOL_LIGHT_DRY_START + 4 * TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_UP)
#define TP_POOL_AROUND_SIDE 4
#define TP_POOL_AROUND_LAYERS 3
#define TP_POOL_AROUND_POINTS (TP_POOL_AROUND_SIDE * TP_POOL_AROUND_SIDE * TP_POOL_AROUND_LAYERS)
// The vec4s after the floor's vertices: the texels, then the light around.
#define TP_POOL_LIGHT_SIZE (TP_POOL_LIGHT_TEXELS + 9 * TP_POOL_AROUND_POINTS)

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

// The same above the water: along it, and down from the rim to the rest level.
TP_INLINE vec2 poolLightDryUv(PoolParams pool, vec3 p, int wall) {
  float along = wall < 2 ? p.z : p.x;
  return vec2((along + pool.box.x) / (2.0f * pool.box.x), (pool.box.y - p.y) / max(pool.box.y - pool.water.x, 1e-6f));
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

// The baked irradiance at p on a wall above the water, but the sun's own
// arrival: the sky over the rim, the sky and the sun the water reflects, the
// pool's light through the surface and the other walls' light.
TP_INLINE vec3 poolLightDryAt(PoolParams pool, vec3 p, vec3 n TP_FLOOR_VERTICES_PARAM) {
  int wall = poolLightWall(n);
  int first = TP_POOL_LIGHT_DRY_START + wall * TP_POOL_LIGHT_ALONG * TP_POOL_LIGHT_UP;
  return poolLightGrid(pool, first, TP_POOL_LIGHT_ALONG, TP_POOL_LIGHT_UP, poolLightDryUv(pool, p, wall)
                       TP_FLOOR_VERTICES_ARG);
}

// Where point k of the light around's grid is.
TP_INLINE vec3 poolAroundPoint(PoolParams pool, int k) {
  int i = k % TP_POOL_AROUND_SIDE, j = (k / TP_POOL_AROUND_SIDE) % TP_POOL_AROUND_SIDE;
  int l = k / (TP_POOL_AROUND_SIDE * TP_POOL_AROUND_SIDE);
  float cell = 2.0f * pool.box.x / float(TP_POOL_AROUND_SIDE);
  float layer = (pool.water.x - pool.terrain.z) / float(TP_POOL_AROUND_LAYERS);
  return vec3(-pool.box.x + (float(i) + 0.5f) * cell, pool.water.x - (float(l) + 0.5f) * layer,
              -pool.box.x + (float(j) + 0.5f) * cell);
}

// The light around p (SH9 of the radiance arriving at it), trilinear
// between the grid's points, held at the outer ones.
TP_INLINE Sh9 poolLightAround(PoolParams pool, vec3 p TP_FLOOR_VERTICES_PARAM) {
  const int side = TP_POOL_AROUND_SIDE, layers = TP_POOL_AROUND_LAYERS;
  vec3 g = vec3((p.x + pool.box.x) / (2.0f * pool.box.x) * float(side),
                (pool.water.x - p.y) / (pool.water.x - pool.terrain.z) * float(layers),
                (p.z + pool.box.x) / (2.0f * pool.box.x) * float(side)) -
           0.5f;
  g = clamp(g, vec3(0.0f), vec3(float(side - 1), float(layers - 1), float(side - 1)));
  int i = min(int(floor(g.x)), side - 2), l = min(int(floor(g.y)), layers - 2), j = min(int(floor(g.z)), side - 2);
  vec3 f = g - vec3(float(i), float(l), float(j));
  int first = int(pool.noise.z * pool.noise.z) + TP_POOL_LIGHT_TEXELS;
  Sh9 sh;
  for (int m = 0; m < 9; ++m) sh.c[m] = vec4(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
    float w = (dx == 1 ? f.x : 1.0f - f.x) * (dy == 1 ? f.y : 1.0f - f.y) * (dz == 1 ? f.z : 1.0f - f.z);
    int k = first + 9 * (((l + dy) * side + j + dz) * side + i + dx);
    for (int m = 0; m < 9; ++m) sh.c[m] += w * floorVertices[k + m];
  }
  return sh;
}

// The sun's and the sky's irradiance on an object (a sphere, a box) at p
// with normal n, `sunShare` of the sun's. In the pool under the water's
// rest level: the sun through the flat surface, and the pool's light around
// it; elsewhere the sun and the open sky (SH9, the ground's light below the
// horizon).
TP_INLINE vec3 objectIrradiance(PoolParams pool, FrameUniforms frame, vec3 p, vec3 n,
                                float sunShare TP_FLOOR_VERTICES_PARAM) {
  if (underRestLevel(pool, p) && max(abs(p.x), abs(p.z)) < pool.box.x)
    return sunShare * sunThroughFlatWater(pool, frame, p, n) +
           sh9Irradiance(poolLightAround(pool, p TP_FLOOR_VERTICES_ARG), n);
  return openAirIrradiance(frame, n, sunShare);
}

// The sun's and the sky's irradiance on a surface of the pool at p with
// normal n, `sunShare` of the sun's. Under the rest level the sun through
// the flat surface and the baked light; a wall above the water the sun and
// its own baked light; without water the open sky's (SH9) and the sun's.
TP_INLINE vec3 poolIrradiance(PoolParams pool, FrameUniforms frame, vec3 p, vec3 n, float sunShare
                              TP_FLOOR_VERTICES_PARAM) {
  if (underRestLevel(pool, p))
    return sunShare * sunThroughFlatWater(pool, frame, p, n) + poolLightAt(pool, p, n TP_FLOOR_VERTICES_ARG);
  if (pool.water.w > 0.0f && abs(n.y) < 0.5f)
    return sunIrradianceOn(frame, n, sunShare) + poolLightDryAt(pool, p, n TP_FLOOR_VERTICES_ARG);
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
