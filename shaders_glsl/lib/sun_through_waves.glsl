// The sun through the waves at a surface that may lie above the water or
// below it: the walls, the objects. The includer declares the simulated
// cells, `waterCells` (shared/water.h's WaterCell, n^2 of them: the pool's
// water.w), and the caustics texture.
#ifndef TP_LIB_SUN_THROUGH_WAVES
#define TP_LIB_SUN_THROUGH_WAVES
#include "shared/pool.h"
#include "lib/caustics_lookup.glsl"

// Whether p lies in the pool under the water's surface: below the surface
// over it, bilinear between the cells' centres and held at the edge cells'
// heights out to the walls (as the caustics' mesh reaches them). Above the
// water a wave draws down, p is in the air, whatever the rest level. With no
// water simulated, under the rest level.
bool underTheWater(PoolParams pool, vec3 p) {
  if (max(abs(p.x), abs(p.z)) > pool.box.x) return false;
  const int n = int(pool.water.w);
  if (n < 2) return p.y < pool.water.x;
  const vec2 g = clamp((p.xz / (2.0 * pool.box.x) + 0.5) * float(n) - 0.5, vec2(0.0), vec2(float(n - 1)));
  const ivec2 i = min(ivec2(g), ivec2(n - 2));
  const vec2 f = g - vec2(i);
  const int k = i.y * n + i.x;
  const float below = mix(waterCells[k].u, waterCells[k + 1].u, f.x);
  const float above = mix(waterCells[k + n].u, waterCells[k + n + 1].u, f.x);
  return p.y < pool.water.x + mix(below, above, f.y);
}

// The caustics texture's ratio at p under the water (causticsRatio), 1 above it.
float sunThroughWaves(sampler2D caustics, PoolParams pool, vec3 toSun, vec3 p) {
  return underTheWater(pool, p) ? causticsRatio(caustics, pool, toSun, p) : 1.0;
}

#endif
