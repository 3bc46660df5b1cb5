#version 450
#extension GL_GOOGLE_include_directive : require
// A level square over the pool, drawn into the depth alone before the walls
// (render/pool.cpp): at a height below which the camera sees everything in
// the pool through the water, whose shader draws over it, the depth test then
// leaves out what is under it. Its outputs are the floor's, for
// pool_floor_depth.frag, whose colour is not written.
#include "shared/frame.h"
#include "shared/pool.h"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(push_constant) uniform Push { vec4 height; };  // x: the square's height (world metres)
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  const ivec2 corners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  const vec2 xz = (vec2(corners[gl_VertexIndex]) * 2.0 - 1.0) * pool.box.x;
  worldPosition = vec3(xz.x, height.x, xz.y);
  worldNormal = vec3(0.0, 1.0, 0.0);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
