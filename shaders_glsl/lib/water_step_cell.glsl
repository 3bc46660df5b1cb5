// One step of one cell, read from the including shader's `vec4 src[]` buffer
// (declared before the include): shared by the one-step and the active-tile
// shaders, so that both give the same bits.
#ifndef TP_LIB_WATER_STEP_CELL
#define TP_LIB_WATER_STEP_CELL
#include "lib/water_update.glsl"

// The new (x, u, z, v) of cell p of the state in src.
vec4 waterStepCell(WaterStepParams params, ivec2 p) {
  const int n = int(params.n);
  const int row = p.y * n;
  const int west = row + waterNeighbour(p.x - 1, n, params.boundary);
  const int east = row + waterNeighbour(p.x + 1, n, params.boundary);
  const int south = waterNeighbour(p.y - 1, n, params.boundary) * n + p.x;
  const int north = waterNeighbour(p.y + 1, n, params.boundary) * n + p.x;
  const vec4 cell = src[row + p.x];
  const vec2 uv = waterUpdate(params, cell.y, cell.w, src[west].y, src[east].y, src[south].y, src[north].y);
  return vec4(cell.x, uv.x, cell.z, uv.y);
}

#endif
