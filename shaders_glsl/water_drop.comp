#version 450
#extension GL_GOOGLE_include_directive : require
// A drop: adds a smooth raised-cosine bump to the height, in place, and marks
// the tiles it changes so that an active-tile step computes them.
#include "shared/water.h"

layout(local_size_x = TP_WATER_TILE, local_size_y = TP_WATER_TILE) in;
layout(binding = 0) buffer State { vec4 cells[]; };
layout(binding = 1) buffer ChangedAt { uint changedAt[]; };
layout(push_constant) uniform Push { WaterDropParams params; };

#include "lib/water_tile_mark.glsl"

const float PI = 3.14159265358979323846;

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  bool changed = false;
  if (p.x < params.n && p.y < params.n) {
    const uint index = p.y * params.n + p.x;
    const vec2 centre = (vec2(p) + 0.5) * params.h;
    const float r = distance(centre, params.center);
    if (r < params.radius) {
      const vec4 before = cells[index];
      vec4 after = before;
      after.y += params.amplitude * 0.5 * (1.0 + cos(PI * r / params.radius));
      cells[index] = after;
      changed = cellChanged(before, after);
    }
  }
  markTileIfChanged(changed, gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x, params.markStep);
}
