#version 450
#extension GL_GOOGLE_include_directive : require
// A sphere tessellated from gl_VertexIndex (stacks x slices quads).
#include "shared/frame.h"
#include "shared/objects.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { SphereParams params; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  const float pi = 3.14159265358979323846;
  const int slices = int(params.tessellation.y);
  const int quad = gl_VertexIndex / 6, corner = gl_VertexIndex % 6;
  const ivec2 offsets[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  const ivec2 cell = ivec2(quad % slices, quad / slices) + offsets[corner];
  const float phi = 2.0 * pi * float(cell.x) / float(slices);
  const float theta = pi * float(cell.y) / float(params.tessellation.x);
  worldNormal = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
  worldPosition = params.sphere.xyz + params.sphere.w * worldNormal;
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
