#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface: one vertex per simulation cell, read straight from the
// simulation's storage buffer (lib/water_grid.glsl).
#include "shared/frame.h"
#include "lib/water_grid.glsl"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  worldNormal = gridNormal(gl_VertexIndex);
  worldPosition = gridPosition(gl_VertexIndex, 1.0);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
