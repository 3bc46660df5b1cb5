// The simulated grid as the vertex stages read it (no copy): the storage
// buffer at binding 2, the surface's push constants, and each vertex's world
// position and normal (central differences of u, one-sided at the edges).
// Two meshes over it: the grid's own, a vertex at each cell's centre (the
// surface drawn), and the grid reaching the walls, that one with a ring of
// vertices on the walls (the light through the water: the caustics).
#ifndef TP_LIB_WATER_GRID
#define TP_LIB_WATER_GRID
#include "shared/water.h"
#include "shared/water_surface.h"

layout(binding = 2) readonly buffer Cells { WaterCell cells[]; };
layout(push_constant) uniform Push { WaterSurfaceParams surface; };

float heightAt(int i, int j) {
  int n = int(surface.grid.x);
  return cells[clamp(j, 0, n - 1) * n + clamp(i, 0, n - 1)].u;
}

vec3 gridNormal(int vertex) {
  const int n = int(surface.grid.x);
  const int i = vertex % n, j = vertex / n;
  const float h = surface.placement.w;
  // One-sided at the edges (the clamped neighbour is the cell itself): divide by the real spacing.
  const float dx = float(min(i + 1, n - 1) - max(i - 1, 0)) * h;
  const float dz = float(min(j + 1, n - 1) - max(j - 1, 0)) * h;
  const float dudx = (heightAt(i + 1, j) - heightAt(i - 1, j)) / dx;
  const float dudz = (heightAt(i, j + 1) - heightAt(i, j - 1)) / dz;
  return normalize(vec3(-dudx, 1.0, -dudz));
}

// The vertex's world position with its height scaled by `wave` (0: at rest).
vec3 gridPosition(int vertex, float wave) {
  const WaterCell c = cells[vertex];
  return vec3(surface.placement.x + c.x, surface.placement.y + wave * c.u, surface.placement.z + c.z);
}

// The grid reaching the walls: (n + 2)^2 vertices, the inner n^2 the cells'
// centres, the outer ring on the walls. A ring vertex takes its edge cell's
// height, as the walls reflect (the grid's ghost cells copy their
// neighbours), and its normal without the edge cell's slope across the wall:
// the water meets a reflecting wall level across it.
ivec2 wallGridVertex(int vertex) {
  const int side = int(surface.grid.x) + 2;
  return ivec2(vertex % side, vertex / side);
}

int wallGridCell(ivec2 v) {
  const int n = int(surface.grid.x);
  const ivec2 c = clamp(v - 1, 0, n - 1);
  return c.y * n + c.x;
}

vec3 wallGridPosition(int vertex, float wave) {
  const ivec2 v = wallGridVertex(vertex);
  const float h = surface.placement.w, n = float(surface.grid.x);
  // Vertex k of a row lies at (k - 1/2) h from the grid's corner, held within the walls.
  const vec2 xz = clamp(vec2(v) - 0.5, 0.0, n) * h;
  return vec3(surface.placement.x + xz.x, surface.placement.y + wave * cells[wallGridCell(v)].u,
              surface.placement.z + xz.y);
}

vec3 wallGridNormal(int vertex) {
  const ivec2 v = wallGridVertex(vertex);
  const int last = int(surface.grid.x) + 1;
  vec3 normal = gridNormal(wallGridCell(v));
  if (v.x == 0 || v.x == last) normal.x = 0.0;
  if (v.y == 0 || v.y == last) normal.z = 0.0;
  return normalize(normal);
}

#endif
