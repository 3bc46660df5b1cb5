#version 450
#extension GL_GOOGLE_include_directive : require
// The pool floor: an n x n grid over the pool drawn with an index buffer, each
// vertex's height and normal those the water's cast and the reference tracer
// take (render::PoolModel::floorVertices, uploaded once).
#include "shared/shading.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(binding = 5) readonly buffer FloorVertices { vec4 floorVertices[]; };
layout(push_constant) uniform Push { uvec4 grid; };  // x: vertices per side
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  const int n = int(grid.x);
  const vec2 uv = vec2(gl_VertexIndex % n, gl_VertexIndex / n) / float(n - 1);
  const vec2 xz = (uv * 2.0 - 1.0) * pool.box.x;
  const vec4 vertex = floorVertices[gl_VertexIndex];
  worldPosition = vec3(xz.x, vertex.w, xz.y);
  worldNormal = vertex.xyz;
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
