// The accurate refraction mode's cast into the pool, shared with C++ to
// measure it: the walls analytically, the floor as the triangle mesh the
// pool's floor is drawn with and the reference tracer intersects (a grid of
// pool.noise.z vertices per side, two triangles a cell split along the
// diagonal from (i+1, j) to (i, j+1)), walked cell by cell along the ray and
// cut exactly, within the slab between its lowest and highest vertex.
//
// The includer provides the vertices (PoolModel::floorVertices: normal, height),
// row by row: in GLSL a storage buffer `floorVertices`, in C++ the pointer
// each function takes last.
#ifndef TP_SHARED_POOL_TRACE_H
#define TP_SHARED_POOL_TRACE_H
#include "shared/shading.h"

#ifdef __cplusplus
#define TP_FLOOR_VERTICES_PARAM , const vec4* floorVertices
#define TP_FLOOR_VERTICES_ARG , floorVertices
#else
#define TP_FLOOR_VERTICES_PARAM
#define TP_FLOOR_VERTICES_ARG
#endif

TP_BEGIN

TP_INLINE vec4 poolFloorVertex(PoolParams pool, int i, int j TP_FLOOR_VERTICES_PARAM) {
  return floorVertices[j * int(pool.noise.z) + i];
}

// Floor grid coordinates per metre: vertex (i, j) at (i, j), the pool's -x,
// -z corner at 0.
TP_INLINE float poolFloorGridScale(PoolParams pool) { return 0.5f * float(int(pool.noise.z) - 1) / pool.box.x; }

// The floor's height at cell-local coordinates f (0..1 each way) of the cell
// whose heights are a (i, j), b (i+1, j), c (i, j+1), d (i+1, j+1), in the
// triangle f lies in.
TP_INLINE float poolCellHeight(vec4 abcd, vec2 f) {
  if (f.x + f.y <= 1.0f) return abcd.x + (abcd.y - abcd.x) * f.x + (abcd.z - abcd.x) * f.y;
  return abcd.w + (abcd.z - abcd.w) * (1.0f - f.x) + (abcd.y - abcd.w) * (1.0f - f.y);
}

// The floor's shading normal at xz: its triangle's vertex normals
// interpolated, as the rasterizer interpolates them where the floor is drawn.
TP_INLINE vec3 poolFloorMeshNormal(PoolParams pool, vec2 xz TP_FLOOR_VERTICES_PARAM) {
  int cells = int(pool.noise.z) - 1;
  vec2 g = (xz + pool.box.x) * poolFloorGridScale(pool);
  int i = clamp(int(floor(g.x)), 0, cells - 1), j = clamp(int(floor(g.y)), 0, cells - 1);
  vec2 f = clamp(g - vec2(float(i), float(j)), vec2(0.0f), vec2(1.0f));
  vec4 a = poolFloorVertex(pool, i, j TP_FLOOR_VERTICES_ARG);
  vec4 b = poolFloorVertex(pool, i + 1, j TP_FLOOR_VERTICES_ARG);
  vec4 c = poolFloorVertex(pool, i, j + 1 TP_FLOOR_VERTICES_ARG);
  vec4 d = poolFloorVertex(pool, i + 1, j + 1 TP_FLOOR_VERTICES_ARG);
  // Each component of the normal interpolated as the heights are.
  return normalize(vec3(poolCellHeight(vec4(a.x, b.x, c.x, d.x), f), poolCellHeight(vec4(a.y, b.y, c.y, d.y), f),
                        poolCellHeight(vec4(a.z, b.z, c.z, d.z), f)));
}

// Where along [s0, s1] the ray (height y0 + s dy, cell-local position
// f0 + s df) first goes under the floor of one cell, or -1. Within each
// triangle the floor and the ray are linear in s, so the cut is exact.
TP_INLINE float poolCellCut(vec4 abcd, vec2 f0, vec2 df, float y0, float dy, float s0, float s1) {
  // The diagonal f.x + f.y = 1 splits [s0, s1] in two pieces at most.
  float sDiagonal = df.x + df.y != 0.0f ? (1.0f - f0.x - f0.y) / (df.x + df.y) : s1;
  float split = clamp(sDiagonal, s0, s1);
  for (int piece = 0; piece < 2; ++piece) {
    float a = piece == 0 ? s0 : split;
    float b = piece == 0 ? split : s1;
    if (piece == 1 && a >= b) break;
    // Each triangle's plane at the piece's ends; the mesh is continuous across
    // the diagonal, so an end on it may take either.
    float ha = poolCellHeight(abcd, f0 + a * df), hb = poolCellHeight(abcd, f0 + b * df);
    float ea = y0 + a * dy - ha, eb = y0 + b * dy - hb;
    if (ea <= 0.0f) return a;
    if (eb <= 0.0f) return a + (b - a) * (ea / (ea - eb));
  }
  return -1.0f;
}

// The first wall or floor point along origin + s dir (origin inside the pool).
TP_INLINE PoolHit tracePool(PoolParams pool, vec3 origin, vec3 dir TP_FLOOR_VERTICES_PARAM) {
  vec2 walls = poolWallDistances(pool, origin, dir);
  float sWall = max(min(walls.x, walls.y), 0.0f);
  // Where the ray goes under the floor; one exit, after the walk, so that
  // every lane of a quad leaves its loop with its own answer.
  float sFloor = -1.0f;
  if (dir.y < 0.0f) {
    float lowest = pool.terrain.z, highest = pool.terrain.w;
    float sIn = max((highest - origin.y) / dir.y, 0.0f);
    float sLowest = (lowest - origin.y) / dir.y;
    float sOut = min(sLowest, sWall);
    int cells = int(pool.noise.z) - 1;
    float scale = poolFloorGridScale(pool);
    vec2 g0 = (vec2(origin.x, origin.z) + pool.box.x) * scale;
    vec2 dg = vec2(dir.x, dir.z) * scale;
    vec2 gIn = g0 + sIn * dg;
    int i = clamp(int(floor(gIn.x)), 0, cells - 1), j = clamp(int(floor(gIn.y)), 0, cells - 1);
    int stepI = dg.x >= 0.0f ? 1 : -1, stepJ = dg.y >= 0.0f ? 1 : -1;
    float s = sIn;
    // A ray crosses each column and row of cells once at most.
    for (int k = 0; k < 2 * cells && s <= sOut; ++k) {
      float sx = dg.x != 0.0f ? (float(i + (stepI > 0 ? 1 : 0)) - g0.x) / dg.x : 1e30f;
      float sz = dg.y != 0.0f ? (float(j + (stepJ > 0 ? 1 : 0)) - g0.y) / dg.y : 1e30f;
      float sExit = min(min(sx, sz), sOut);
      vec4 abcd = vec4(poolFloorVertex(pool, i, j TP_FLOOR_VERTICES_ARG).w,
                       poolFloorVertex(pool, i + 1, j TP_FLOOR_VERTICES_ARG).w,
                       poolFloorVertex(pool, i, j + 1 TP_FLOOR_VERTICES_ARG).w,
                       poolFloorVertex(pool, i + 1, j + 1 TP_FLOOR_VERTICES_ARG).w);
      sFloor = poolCellCut(abcd, g0 - vec2(float(i), float(j)), dg, origin.y, dir.y, s, max(sExit, s));
      if (sFloor >= 0.0f || sExit >= sOut) break;
      s = sExit;
      if (sx < sz)
        i += stepI;
      else
        j += stepJ;
      if (i < 0 || i >= cells || j < 0 || j >= cells) break;
    }
    // Below its lowest vertex the ray is under the floor: rounding let it
    // slip through an edge, or the floor is flat and met at the slab's top.
    if (sFloor < 0.0f && sLowest < sWall) sFloor = sLowest;
  }
  if (sFloor >= 0.0f) {
    vec3 hit = origin + sFloor * dir;
    return poolHit(sFloor, hit, poolFloorMeshNormal(pool, vec2(hit.x, hit.z) TP_FLOOR_VERTICES_ARG), true);
  }
  vec3 wallPoint = origin + sWall * dir;
  return poolHit(sWall, wallPoint, poolWallNormal(walls, dir), false);
}

TP_END

#endif
