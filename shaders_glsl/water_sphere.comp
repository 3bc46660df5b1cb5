#version 450
#extension GL_GOOGLE_include_directive : require
// A sphere moving through the water displaces it by volume (as in Evan
// Wallace's WebGL Water, but exact per column): each column's height changes
// by the length of the sphere's vertical chord below the rest level at the old
// position minus that at the new one, so the water's volume changes by exactly
// minus the change of the sphere's submerged volume (as the grid samples it).
// Marks the tiles it changes so that an active-tile step computes them.
#include "shared/water.h"

layout(local_size_x = TP_WATER_TILE, local_size_y = TP_WATER_TILE) in;
layout(binding = 0) buffer State { vec4 cells[]; };
layout(binding = 1) buffer ChangedAt { uint changedAt[]; };
layout(push_constant) uniform Push { WaterSphereParams params; };

#include "lib/water_tile_mark.glsl"

float submergedChord(vec3 center, float radius, vec2 column, float level) {
  const vec2 d = column - center.xz;
  const float r2 = radius * radius - dot(d, d);
  if (r2 <= 0.0) return 0.0;
  const float halfChord = sqrt(r2);
  const float bottom = center.y - halfChord;
  const float top = min(center.y + halfChord, level);
  return max(top - bottom, 0.0);
}

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  bool changed = false;
  if (p.x < params.n && p.y < params.n) {
    const vec2 column = (vec2(p) + 0.5) * params.h;
    const float radius = params.oldCenter.w, level = params.newCenter.w;
    const float before = submergedChord(params.oldCenter.xyz, radius, column, level);
    const float after = submergedChord(params.newCenter.xyz, radius, column, level);
    if (before != after) {
      const uint index = p.y * params.n + p.x;
      const vec4 old = cells[index];
      vec4 moved = old;
      moved.y += before - after;
      cells[index] = moved;
      changed = cellChanged(old, moved);
    }
  }
  markTileIfChanged(changed, gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x, params.markStep);
}
