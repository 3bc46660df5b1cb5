#version 450
#extension GL_GOOGLE_include_directive : require
// The pool floor: an n x n grid over the pool drawn with an index buffer, its
// height and normal from the shared terrain function (shared/pool.h).
#include "shared/shading.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(push_constant) uniform Push { uvec4 grid; };  // x: vertices per side
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  const int n = int(grid.x);
  const vec2 uv = vec2(gl_VertexIndex % n, gl_VertexIndex / n) / float(n - 1);
  const vec2 xz = (uv * 2.0 - 1.0) * pool.box.x;
  worldPosition = vec3(xz.x, poolFloorHeight(pool, xz), xz.y);
  worldNormal = poolFloorNormal(pool, xz, kPoolFloorNormalSpacing);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
