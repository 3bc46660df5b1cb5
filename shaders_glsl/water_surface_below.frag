#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface seen from under the water: the back faces of the mesh,
// drawn by their own pipeline (front faces culled) in both refraction modes.
// A separate draw rather than a branch on gl_FrontFacing: lavapipe runs both
// sides of a branch, and the cast below the surface is the costliest code here.
#include "lib/water_shading.glsl"

#ifdef TP_CLEAR_AMBIENT
// The opaque surfaces' ambient part, which the resolve pass takes AO from:
// none where the water is seen.
layout(location = 1) out vec4 ambient;
#endif

void main() {
  color = shadeFromBelow(normalize(worldPosition - frame.cameraPosition.xyz), normalize(worldNormal));
#ifdef TP_CLEAR_AMBIENT
  ambient = vec4(0.0);
#endif
}
