#version 450
#extension GL_GOOGLE_include_directive : require
// Lists the frame's tiles that a pass is to work on (shared/screen_tiles.h):
// those tagged in one of two frames, or inside a rectangle; and writes the
// indirect dispatch over them. One workgroup: it counts in shared memory, so
// no counter has to be cleared between frames. The tags are frame numbers,
// so no tag has to be cleared either.
#include "shared/screen_tiles.h"

layout(local_size_x = 256) in;
layout(binding = 0) readonly buffer TileTags { uint tileTags[]; };
layout(binding = 1) writeonly buffer TileList { uint tileList[]; };
layout(push_constant) uniform Push { ScreenTileListParams params; };

shared uint listed;

bool inRect(uint t) {
  const uvec2 tile = screenTileAt(t, params.tags.w);
  return all(greaterThanEqual(tile, params.rect.xy)) && all(lessThan(tile, params.rect.zw));
}

void main() {
  if (gl_LocalInvocationIndex == 0u) listed = 0u;
  memoryBarrierShared();
  barrier();
  for (uint t = gl_LocalInvocationIndex; t < params.tags.z; t += gl_WorkGroupSize.x) {
    const uint tag = tileTags[t];
    if (tag == params.tags.x || tag == params.tags.y || inRect(t))
      tileList[TP_SCREEN_TILE_LIST_HEADER + atomicAdd(listed, 1u)] = t;
  }
  memoryBarrierShared();
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    tileList[0] = listed;
    tileList[1] = 1u;
    tileList[2] = 1u;
  }
}
