// The update of one water cell, shared by the one-step and the tiled
// multi-step shaders so that both give the same bits ("precise" keeps the
// compiler from fusing or reordering differently in the two contexts).
#ifndef TP_LIB_WATER_UPDATE
#define TP_LIB_WATER_UPDATE
#include "shared/water.h"

// New (u, v) of a cell from its height u, velocity v and the heights and
// velocities of its west, east, south and north neighbours (ghost cells
// already resolved); `atWall`: the cell lies along the grid's edge.
//
// The Laplacian is a sum of differences, not (sum of neighbours) - 4u: heights
// sit on a rest level (around 1, say) far above the waves, and the differences
// of nearby heights are exact in float (Sterbenz), where the sum of four
// heights would round at the level's ulp and feed that noise into v, whose sum
// then random-walks and the volume with it.
vec2 waterUpdate(WaterStepParams p, float u, float v, vec4 uWESN, vec4 vWESN, bool atWall) {
  precise float laplacianH2 = ((uWESN.x - u) + (uWESN.y - u)) + ((uWESN.z - u) + (uWESN.w - u));
  // The grid damping (docs/water-numerics.md): kappa h^2 times the Laplacian
  // of v damps the checkerboard's amplitude at 4 kappa and a long wave of
  // wavenumber k at kappa (h k)^2 / 2, which vanishes as the grid is refined.
  precise float velocityLaplacianH2 = ((vWESN.x - v) + (vWESN.y - v)) + ((vWESN.z - v) + (vWESN.w - v));
  precise float vNew = p.damping * (v + p.waveFactor * laplacianH2) + p.gridDamping * velocityLaplacianH2;
  // Symplectic Euler moves u with the new velocity; the literal forward Euler
  // (kept to show that it is unstable) with the old one.
  precise float uNew = u + p.dt * (p.scheme == TP_WATER_SCHEME_EXPLICIT ? v : vNew);
  if (p.maxDifference > 0.0) {
    // The slope limiter (docs/water-numerics.md): across each edge whose two
    // heights differ by more than maxSlope * h, slopeShare of the excess flows
    // down. What one cell loses its neighbour gains (the neighbour computes
    // the same difference, negated exactly), so the volume is kept; cells
    // whose four edges are within the limit keep their value to the bit.
    const float m = p.maxDifference;
    precise float moved = (waterSlopeExcess(u - uWESN.x, m) + waterSlopeExcess(u - uWESN.y, m)) +
                          (waterSlopeExcess(u - uWESN.z, m) + waterSlopeExcess(u - uWESN.w, m));
    uNew = uNew - p.slopeShare * moved;
  }
  // Along the pool's walls, water over the rim leaves the pool: the cell
  // keeps the rim's height and stops rising (docs/water-numerics.md, "The rim").
  if (atWall && p.boundary == TP_WATER_BOUNDARY_CLAMP && uNew > p.spillHeight) {
    uNew = p.spillHeight;
    vNew = min(vNew, 0.0);
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
