#version 450
#extension GL_GOOGLE_include_directive : require
// Arbitrary output variables of the surfaces: world normal, world position
// and view depth Z (distance along the camera's -z), for the EXR's N, P and Z.
#include "shared/frame.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 normalOut;    // xyz: unit world normal
layout(location = 1) out vec4 positionOut;  // xyz: world position; w: view depth Z
layout(binding = 0) uniform Frame { FrameUniforms frame; };

void main() {
  normalOut = vec4(normalize(worldNormal), 0.0);
  positionOut = vec4(worldPosition, -(frame.view * vec4(worldPosition, 1.0)).z);
}
