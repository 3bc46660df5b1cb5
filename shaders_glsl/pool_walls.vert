#version 450
#extension GL_GOOGLE_include_directive : require
// The pool's four inner walls, from the rim down to the lowest floor, facing
// in: the bands PoolWallsParams names (shared/pool.h).
#include "shared/frame.h"
#include "shared/pool.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(push_constant) uniform Push { PoolWallsParams walls; };

void main() {
  const float s = pool.box.x;
  // Each wall: a corner, the direction along it, and its inward normal.
  const vec3 starts[4] = vec3[](vec3(-s, 0, -s), vec3(s, 0, -s), vec3(s, 0, s), vec3(-s, 0, s));
  const vec3 alongs[4] = vec3[](vec3(1, 0, 0), vec3(0, 0, 1), vec3(-1, 0, 0), vec3(0, 0, -1));
  const vec3 normals[4] = vec3[](vec3(0, 0, 1), vec3(-1, 0, 0), vec3(0, 0, -1), vec3(1, 0, 0));
  const ivec2 corners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  // Four quads a band, one a wall, from the band walls.bands.x on.
  const int quad = gl_VertexIndex / 6, wall = quad % 4;
  const uint band = walls.bands.x + uint(quad / 4);
  const ivec2 c = corners[gl_VertexIndex % 6];
  const float y = poolWallBandTop(pool, band + uint(c.y));
  worldPosition = starts[wall] + float(c.x) * 2.0 * s * alongs[wall] + vec3(0.0, y, 0.0);
  worldNormal = normals[wall];
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
