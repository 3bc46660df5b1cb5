#version 450
#extension GL_GOOGLE_include_directive : require
// A square of the plane y = height, generated from gl_VertexIndex (two triangles).
#include "shared/frame.h"
#include "shared/ground.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { GroundParams ground; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  vec2 c = corners[gl_VertexIndex] * ground.plane.x;
  worldPosition = vec3(c.x, ground.plane.y, c.y);
  worldNormal = vec3(0.0, 1.0, 0.0);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
