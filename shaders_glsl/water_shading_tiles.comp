#version 450
#extension GL_GOOGLE_include_directive : require
// Lists the tiles the water's G-buffer pass tagged this frame, and writes the
// indirect dispatch of water_surface_deferred.comp over them. One workgroup:
// it counts in shared memory, so no counter has to be cleared between frames.
// The tags are frame numbers, so no tag has to be cleared either.
#include "shared/water_surface.h"

layout(local_size_x = 256) in;
layout(binding = 0) readonly buffer TileTags { uint tileTags[]; };
layout(binding = 1) writeonly buffer TileList { uint tileList[]; };  // the dispatch's x, y, z, a pad, then the tiles
layout(push_constant) uniform Push { uvec4 params; };                 // x: the frame's tag, y: tiles in all

shared uint listed;

void main() {
  if (gl_LocalInvocationIndex == 0u) listed = 0u;
  memoryBarrierShared();
  barrier();
  for (uint t = gl_LocalInvocationIndex; t < params.y; t += gl_WorkGroupSize.x) {
    if (tileTags[t] == params.x) tileList[TP_WATER_SHADING_LIST_HEADER + atomicAdd(listed, 1u)] = t;
  }
  memoryBarrierShared();
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    tileList[0] = listed;
    tileList[1] = 1u;
    tileList[2] = 1u;
  }
}
