#version 450
#extension GL_GOOGLE_include_directive : require
// Several water steps per dispatch (temporal blocking): a workgroup loads a
// tile with a halo of HALO cells into shared memory, takes params.steps <= HALO
// steps there (the valid region shrinks by one cell a step), and writes the
// inner (TILE - 2 HALO)^2 cells. Memory traffic per step falls by the number
// of steps; the halo's redundant work is the price.
#include "shared/water.h"

layout(constant_id = 0) const int HALO = 4;
layout(local_size_x = 32, local_size_y = 32) in;
const int TILE = 32;  // = local size: one invocation per cell of the haloed tile
const int INNER = TILE - 2 * HALO;

layout(binding = 0) readonly buffer Src { WaterCell src[]; };
layout(binding = 1) writeonly buffer Dst { WaterCell dst[]; };
layout(binding = 4) readonly buffer Solid { uint solidDepths[]; };
layout(push_constant) uniform Push { WaterStepParams params; };

#include "lib/water_solid.glsl"
#include "lib/water_update.glsl"

shared float su[TILE * TILE];
shared float sv[TILE * TILE];

void main() {
  const int n = int(params.n);
  const ivec2 l = ivec2(gl_LocalInvocationID.xy);
  const ivec2 origin = ivec2(gl_WorkGroupID.xy) * INNER - HALO;
  const ivec2 g = origin + l;  // may lie outside the grid
  const bool wrap = params.boundary == TP_WATER_BOUNDARY_WRAP;
  // Wrap: the haloed tile is a piece of the periodic domain. Clamp: cells off
  // the grid are loaded (clamped) but never read, since neighbour lookups
  // clamp in grid coordinates first.
  const ivec2 load = ivec2(waterNeighbour(g.x, n, params.boundary), waterNeighbour(g.y, n, params.boundary));
  WaterCell c = src[load.y * n + load.x];
  su[l.y * TILE + l.x] = c.u;
  sv[l.y * TILE + l.x] = c.v;

  // Local index of a neighbour: in the tile for wrap, through the grid's clamp otherwise.
  ivec2 west = l - ivec2(1, 0), east = l + ivec2(1, 0), south = l - ivec2(0, 1), north = l + ivec2(0, 1);
  if (!wrap) {
    west.x = clamp(g.x - 1, 0, n - 1) - origin.x;
    east.x = clamp(g.x + 1, 0, n - 1) - origin.x;
    south.y = clamp(g.y - 1, 0, n - 1) - origin.y;
    north.y = clamp(g.y + 1, 0, n - 1) - origin.y;
  }
  // A solid neighbour reads as the cell itself, and a solid cell's height is
  // a ghost of its neighbours' (lib/water_solid.glsl).
  bool solidCell = false;
  const ivec2 west0 = west, east0 = east, south0 = south, north0 = north;  // before the solid ones are replaced
  bvec4 nearer = bvec4(false);
  if (kSolids) {
    const uint depth = waterSolidDepth(load.y * n + load.x);
    solidCell = depth != 0u;
    const int gw = load.y * n + waterNeighbour(g.x - 1, n, params.boundary);
    const int ge = load.y * n + waterNeighbour(g.x + 1, n, params.boundary);
    const int gs = waterNeighbour(g.y - 1, n, params.boundary) * n + load.x;
    const int gn = waterNeighbour(g.y + 1, n, params.boundary) * n + load.x;
    nearer = waterNearer(depth, gw, ge, gs, gn);
    if (waterSolid(gw)) west = l;
    if (waterSolid(ge)) east = l;
    if (waterSolid(gs)) south = l;
    if (waterSolid(gn)) north = l;
  }
  const int steps = int(min(params.steps, uint(HALO)));
  for (int s = 1; s <= steps; ++s) {
    barrier();
    const bool updating = all(greaterThanEqual(l, ivec2(s))) && all(lessThan(l, ivec2(TILE - s)));
    vec2 uv = vec2(0.0);
    if (updating) {
      const int self = l.y * TILE + l.x;
      const int iW = west.y * TILE + west.x, iE = east.y * TILE + east.x;
      const int iS = south.y * TILE + south.x, iN = north.y * TILE + north.x;
      const vec4 uWESN = vec4(su[iW], su[iE], su[iS], su[iN]);
      if (solidCell) {
        const int jW = west0.y * TILE + west0.x, jE = east0.y * TILE + east0.x;
        const int jS = south0.y * TILE + south0.x, jN = north0.y * TILE + north0.x;
        uv = vec2(waterGhostHeight(su[self], vec4(su[jW], su[jE], su[jS], su[jN]), nearer), sv[self]);
      } else {
        const bool atWall = g.x == 0 || g.y == 0 || g.x == n - 1 || g.y == n - 1;
        uv = waterUpdate(params, su[self], sv[self], uWESN, vec4(sv[iW], sv[iE], sv[iS], sv[iN]), atWall);
      }
    }
    barrier();
    if (updating) {
      su[l.y * TILE + l.x] = uv.x;
      sv[l.y * TILE + l.x] = uv.y;
    }
  }
  barrier();
  const bool inner = all(greaterThanEqual(l, ivec2(HALO))) && all(lessThan(l, ivec2(TILE - HALO)));
  if (inner && g.x < n && g.y < n) {
    c.u = su[l.y * TILE + l.x];
    c.v = sv[l.y * TILE + l.x];
    dst[g.y * n + g.x] = c;
  }
}
