#version 450
#extension GL_GOOGLE_include_directive : require
// The glass spheres' back faces (front faces culled): what glass.frag's
// search for the exit point reads, the outward normal and the view depth of
// the nearest back face under each pixel (0 where there is none: cleared).
#include "shared/frame.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 backFace;
layout(binding = 0) uniform Frame { FrameUniforms frame; };

void main() {
  backFace = vec4(normalize(worldNormal), -(frame.view * vec4(worldPosition, 1.0)).z);
}
