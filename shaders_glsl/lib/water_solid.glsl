// The cells the water cannot enter (WaterParams::solid, sim/water_params.hpp),
// as the including shader's `uint solidDepths[]` (declared before the
// include) gives them: one byte a cell, 0 where the cell is open, else its
// distance in cells to the nearest open one (sim::solidDepths). An open cell
// sees its own height and velocity in a solid neighbour's place, as it does
// at the pool's walls, so no water crosses the edge between and the volume
// and the scheme's energy are kept.
//
// A solid cell holds no water. Its height is a ghost that continues the
// water's surface into the box, so that the drawn surface meets the box's
// faces at the water's height: the mean of its neighbours one cell nearer
// the water (the open ones, next to it), each ring of cells a step behind
// the one outside it. A height of its own would tilt the mesh's triangles up
// or down along the box's staircase of cells, and its faces would cut them
// in a saw-tooth.
#ifndef TP_LIB_WATER_SOLID
#define TP_LIB_WATER_SOLID
#include "shared/water.h"

layout(constant_id = TP_SPEC_WATER_SOLIDS) const bool kSolids = false;

uint waterSolidDepth(int k) { return (solidDepths[k >> 2] >> (uint(k & 3) * 8u)) & 255u; }
bool waterSolid(int k) { return waterSolidDepth(k) != 0u; }

// The index to read for neighbour `other` of cell `self`: itself where the
// neighbour is solid.
int waterOpenNeighbour(int self, int other) { return waterSolid(other) ? self : other; }

// Which of the neighbours (west, east, south, north) of a solid cell of
// `depth` lie one cell nearer the water.
bvec4 waterNearer(uint depth, int west, int east, int south, int north) {
  return equal(uvec4(waterSolidDepth(west), waterSolidDepth(east), waterSolidDepth(south), waterSolidDepth(north)),
               uvec4(depth - 1u));
}

// The ghost height of a solid cell whose neighbours have heights `u` and lie
// nearer the water where `nearer` says; its own where none does (a cell
// further than the depths count).
float waterGhostHeight(float own, vec4 u, bvec4 nearer) {
  precise float sum = 0.0;
  float count = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (nearer[k]) {
      sum += u[k];
      count += 1.0;
    }
  }
  return count > 0.0 ? sum / count : own;
}

#endif
