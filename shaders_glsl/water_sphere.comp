#version 450
#extension GL_GOOGLE_include_directive : require
// A sphere moving through the water displaces it by volume (as in Evan
// Wallace's WebGL Water, but exact per column): each column's height changes
// by the length of the sphere's vertical chord below the rest level at the old
// position minus that at the new one, so the water's volume changes by exactly
// minus the change of the sphere's submerged volume (as the grid samples it).
#include "shared/water.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) buffer State { WaterCell cells[]; };
layout(push_constant) uniform Push { WaterSphereParams params; };

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
  if (p.x >= params.n || p.y >= params.n) return;
  const vec2 column = (vec2(p) + 0.5) * params.h;
  const float radius = params.oldCenter.w, level = params.newCenter.w;
  const float before = submergedChord(params.oldCenter.xyz, radius, column, level);
  const float after = submergedChord(params.newCenter.xyz, radius, column, level);
  if (before != after) cells[p.y * params.n + p.x].u += before - after;
}
