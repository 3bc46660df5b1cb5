// One step of one cell, read from the including shader's `vec4 src[]` buffer
// and `uint solidDepths[]` (declared before the include): shared by the
// one-step and the active-tile shaders, so that both give the same bits.
#ifndef TP_LIB_WATER_STEP_CELL
#define TP_LIB_WATER_STEP_CELL
#include "lib/water_solid.glsl"
#include "lib/water_update.glsl"

// The new (x, u, z, v) of cell p of the state in src.
vec4 waterStepCell(WaterStepParams params, ivec2 p) {
  const int n = int(params.n);
  const int row = p.y * n;
  const int self = row + p.x;
  int west = row + waterNeighbour(p.x - 1, n, params.boundary);
  int east = row + waterNeighbour(p.x + 1, n, params.boundary);
  int south = waterNeighbour(p.y - 1, n, params.boundary) * n + p.x;
  int north = waterNeighbour(p.y + 1, n, params.boundary) * n + p.x;
  if (kSolids) {
    const uint depth = waterSolidDepth(self);
    if (depth != 0u) {
      const vec4 cell = src[self];
      const vec4 u = vec4(src[west].y, src[east].y, src[south].y, src[north].y);
      return vec4(cell.x, waterGhostHeight(cell.y, u, waterNearer(depth, west, east, south, north)), cell.z, cell.w);
    }
    west = waterOpenNeighbour(self, west);
    east = waterOpenNeighbour(self, east);
    south = waterOpenNeighbour(self, south);
    north = waterOpenNeighbour(self, north);
  }
  const vec4 cell = src[self];
  const vec4 w = src[west], e = src[east], s = src[south], nn = src[north];
  const bool atWall = p.x == 0 || p.y == 0 || p.x == n - 1 || p.y == n - 1;
  const vec2 uv =
      waterUpdate(params, cell.y, cell.w, vec4(w.y, e.y, s.y, nn.y), vec4(w.w, e.w, s.w, nn.w), atWall);
  return vec4(cell.x, uv.x, cell.z, uv.y);
}

#endif
