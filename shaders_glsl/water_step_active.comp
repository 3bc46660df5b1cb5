#version 450
#extension GL_GOOGLE_include_directive : require
// One step over whole tiles: all of them, or those a list names (the tiles
// within reach of the last step's changes). Every cell it computes gets the
// bits water_step.comp gives (same waterStepCell); a tile not computed keeps,
// in dst, the state of two steps ago, which equals the last one there (see
// sim/water_tiles.hpp for why that is the step's result).
#include "shared/water.h"

layout(local_size_x = TP_WATER_TILE, local_size_y = TP_WATER_TILE) in;
layout(binding = 0) readonly buffer Src { vec4 src[]; };
layout(binding = 1) writeonly buffer Dst { vec4 dst[]; };
layout(binding = 2) buffer ChangedAt { uint changedAt[]; };
layout(binding = 3) readonly buffer TileList { uint tileList[]; };
layout(binding = 4) readonly buffer Solid { uint solidDepths[]; };
layout(push_constant) uniform Push { WaterTileStepParams params; };

#include "lib/water_step_cell.glsl"
#include "lib/water_tile_mark.glsl"

void main() {
  const uint side = params.tilesPerSide;
  const uint tile = params.fromList != 0u ? tileList[gl_WorkGroupID.x] : gl_WorkGroupID.y * side + gl_WorkGroupID.x;
  const ivec2 p = ivec2(uvec2(tile % side, tile / side) * TP_WATER_TILE + gl_LocalInvocationID.xy);
  const int n = int(params.step.n);
  bool changed = false;
  if (p.x < n && p.y < n) {
    const vec4 after = waterStepCell(params.step, p);
    changed = cellChanged(src[p.y * n + p.x], after);
    dst[p.y * n + p.x] = after;
  }
  markTileIfChanged(changed, tile, params.stepIndex);
}
