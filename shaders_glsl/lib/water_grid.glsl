// The simulated grid as the vertex stages read it (no copy): the storage
// buffer at binding 2, the surface's push constants, and each vertex's world
// position and normal (central differences of u, one-sided at the edges).
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

#endif
