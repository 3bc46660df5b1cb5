#version 450
#extension GL_GOOGLE_include_directive : require
// A box from gl_VertexIndex: 6 faces of two triangles, outward, turned by its yaw.
#include "shared/frame.h"
#include "shared/objects.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { BoxParams params; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  const int face = gl_VertexIndex / 6, corner = gl_VertexIndex % 6;
  const int axis = face / 2;
  const float side = (face % 2 == 0) ? 1.0 : -1.0;
  // The face's two in-plane axes, ordered so that (u, v, normal) is right-handed.
  vec3 normal = vec3(0.0), u = vec3(0.0), v = vec3(0.0);
  normal[axis] = side;
  u[(axis + 1) % 3] = 1.0;
  v[(axis + 2) % 3] = side;
  const vec2 offsets[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  const vec3 local = (normal + offsets[corner].x * u + offsets[corner].y * v) * params.halfSize.xyz;
  const vec3 ax = boxAxisX(params.center.w), az = boxAxisZ(params.center.w);
  worldPosition = params.center.xyz + local.x * ax + vec3(0.0, local.y, 0.0) + local.z * az;
  worldNormal = normal.x * ax + vec3(0.0, normal.y, 0.0) + normal.z * az;
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
