// The update of one water cell, shared by the one-step and the tiled
// multi-step shaders so that both give the same bits ("precise" keeps the
// compiler from fusing or reordering differently in the two contexts).
#ifndef TP_LIB_WATER_UPDATE
#define TP_LIB_WATER_UPDATE
#include "shared/water.h"

// New (u, v) of a cell from its height u, velocity v and the heights of its
// west, east, south and north neighbours (ghost cells already resolved).
vec2 waterUpdate(WaterStepParams p, float u, float v, float uW, float uE, float uS, float uN) {
  precise float neighbours = ((uW + uE) + (uS + uN));
  precise float laplacianH2 = neighbours - 4.0 * u;
  precise float vNew = p.damping * (v + p.waveFactor * laplacianH2);
  // Symplectic Euler moves u with the new velocity; the literal forward Euler
  // (kept to show that it is unstable) with the old one.
  precise float uNew = u + p.dt * (p.scheme == TP_WATER_SCHEME_EXPLICIT ? v : vNew);
  if (p.maxOffset > 0.0) {
    precise float average = 0.25 * neighbours;
    uNew = average + clamp(uNew - average, -p.maxOffset, p.maxOffset);
  }
  return vec2(uNew, vNew);
}

// Index of a neighbour along one axis under the boundary rule: clamp repeats
// the edge cell (reflective walls), wrap is periodic.
// i may lie up to a tile's halo outside the grid; % is only defined in GLSL
// for non-negative operands, hence the shift by a multiple of n.
int waterNeighbour(int i, int n, uint boundary) {
  if (boundary == TP_WATER_BOUNDARY_WRAP) return (i + 64 * n) % n;
  return clamp(i, 0, n - 1);
}

#endif
