#version 450
#extension GL_GOOGLE_include_directive : require
// A drop: adds a smooth raised-cosine bump to the height, in place.
#include "shared/water.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) buffer State { WaterCell cells[]; };
layout(push_constant) uniform Push { WaterDropParams params; };

const float PI = 3.14159265358979323846;

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= params.n || p.y >= params.n) return;
  const uint index = p.y * params.n + p.x;
  const vec2 centre = (vec2(p) + 0.5) * params.h;
  const float r = distance(centre, params.center);
  if (r < params.radius) cells[index].u += params.amplitude * 0.5 * (1.0 + cos(PI * r / params.radius));
}
