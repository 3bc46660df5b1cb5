#version 450
#extension GL_GOOGLE_include_directive : require
// Lists the tiles the next step must compute: those with a tile changed at
// the last step in their 3x3 neighbourhood (the stencil reaches one cell, so
// one tile of halo), and writes the indirect dispatch over the list. One
// workgroup: it counts in shared memory, so no counter has to be cleared
// between steps.
#include "shared/water.h"

layout(local_size_x = 256) in;
layout(binding = 0) readonly buffer ChangedAt { uint changedAt[]; };
layout(binding = 1) writeonly buffer TileList { uint tileList[]; };
layout(binding = 2) buffer Counters { WaterTileCounters counters; };
layout(push_constant) uniform Push { WaterTileListParams params; };

shared uint listed;

bool changedNear(ivec2 tile) {
  const int side = int(params.tilesPerSide);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = tile + ivec2(dx, dy);
      if (params.boundary == TP_WATER_BOUNDARY_WRAP) {
        q = (q + side) % side;
      } else if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(side)))) {
        continue;  // clamp: the ghost cells beyond the edge are the tile's own
      }
      if (changedAt[q.y * side + q.x] == params.changedStep) return true;
    }
  }
  return false;
}

void main() {
  if (gl_LocalInvocationIndex == 0u) listed = 0u;
  memoryBarrierShared();
  barrier();
  const uint side = params.tilesPerSide;
  for (uint t = gl_LocalInvocationIndex; t < side * side; t += gl_WorkGroupSize.x) {
    if (changedNear(ivec2(t % side, t / side))) tileList[atomicAdd(listed, 1u)] = t;
  }
  memoryBarrierShared();
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    counters.groupsX = listed;
    counters.groupsY = 1u;
    counters.groupsZ = 1u;
    if (params.accumulate != 0u) {
      const uint low = counters.totalLow + listed;
      if (low < listed) counters.totalHigh += 1u;
      counters.totalLow = low;
    }
  }
}
