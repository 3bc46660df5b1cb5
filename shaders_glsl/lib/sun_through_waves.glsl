// The sun through the waves at a surface that may lie above the water or
// below it: the walls, the objects. The includer declares the simulated
// cells, `waterCells` (shared/water.h's WaterCell, n^2 of them: the pool's
// water.w), and the caustics texture.
#ifndef TP_LIB_SUN_THROUGH_WAVES
#define TP_LIB_SUN_THROUGH_WAVES
#include "shared/pool.h"
#include "shared/water_surface.h"
#include "lib/caustics_lookup.glsl"

// Whether p lies in the pool under the water's surface: below the surface
// mesh over it (shared/water_surface.h's gridQuadAt and gridQuadHeight, as
// the camera's medium asks it), held at the edge cells' heights out to the
// walls (as the caustics' mesh reaches them). Above the water a wave draws
// down, p is in the air, whatever the rest level. With no water simulated,
// under the rest level. The walls themselves count: not overWaterSquare.
bool underTheWater(PoolParams pool, vec3 p) {
  if (max(abs(p.x), abs(p.z)) > pool.box.x) return false;
  const int n = int(pool.water.w);
  if (n < 2) return p.y < pool.water.x;
  // The grid as the pool's uniforms place it, over the pool's square; only its placement is read.
  const WaterSurfaceParams grid = WaterSurfaceParams(
      vec4(-pool.box.x, pool.water.x, -pool.box.x, 2.0 * pool.box.x / float(n)), vec4(0.0), vec4(0.0), uvec4(n, 0, 0, 0));
  const vec4 quad = gridQuadAt(grid, p.xz);
  const int k = int(quad.y) * n + int(quad.x);
  const vec4 corners = vec4(waterCells[k].u, waterCells[k + 1].u, waterCells[k + n].u, waterCells[k + n + 1].u);
  return p.y < pool.water.x + gridQuadHeight(corners, quad.zw);
}

// The caustics texture's ratio at p under the water (causticsRatio), 1 above it.
float sunThroughWaves(sampler2D caustics, PoolParams pool, vec3 toSun, vec3 p) {
  return underTheWater(pool, p) ? causticsRatio(caustics, pool, toSun, p) : 1.0;
}

#endif
