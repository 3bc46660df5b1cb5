#version 450
#extension GL_GOOGLE_include_directive : require
// The ground: the square of the plane y = height, less the pool's square hole
// of half size plane.w (0: no hole), from gl_VertexIndex.
#include "shared/frame.h"
#include "shared/ground.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { GroundParams ground; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  // A square ring: four trapezoids between the outer square and the hole, each
  // pair sharing a whole edge (no T-junctions, so no cracks between them).
  const float e = ground.plane.x, hole = ground.plane.w;
  const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
  const int side = gl_VertexIndex / 6, k = gl_VertexIndex % 6;
  const vec2 outer0 = corners[side] * e, outer1 = corners[(side + 1) % 4] * e;
  const vec2 inner0 = corners[side] * hole, inner1 = corners[(side + 1) % 4] * hole;
  const vec2 quad[6] = vec2[](outer0, inner0, outer1, outer1, inner0, inner1);
  worldPosition = vec3(quad[k].x, ground.plane.y, quad[k].y);
  worldNormal = vec3(0.0, 1.0, 0.0);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
