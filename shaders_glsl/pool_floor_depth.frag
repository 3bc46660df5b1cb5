#version 450
#extension GL_GOOGLE_include_directive : require
// The pool floor's depth and normal, and no light: drawn instead of
// pool_floor.frag in frames whose camera sees the floor only through the
// water (shading/water_model.cpp's floorSeenOnlyThroughWater), whose shader
// draws over it with what its refracted rays see. AO still needs the floor's
// depth and normal. The same for the walls' bands under the water in those
// frames (shared/pool.h).
#include "shared/frame.h"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };

void main() {
  color = vec4(0.0);
  writeGbuffer(frame, normalize(worldNormal), vec3(0.0));
}
