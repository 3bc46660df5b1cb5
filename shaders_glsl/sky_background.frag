#version 450
#extension GL_GOOGLE_include_directive : require
// The sky behind everything: the view ray through each pixel looks up the
// equirectangular sky texture. Drawn in the ground's pass, over its G-buffer
// (TP_COLOR_ONLY: a frame without one), where it leaves no surface.
#include "shared/frame.h"
#include "shared/shading.h"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D skyTexture;

void main() {
  vec4 far = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - frame.cameraPosition.xyz);
  // Level 0: the implicit level would jump to the coarsest where u wraps
  // round (its derivative there spans the texture).
  color = vec4(textureLod(skyTexture, directionToEquirect(dir), 0.0).rgb, 1.0);
  writeNoSurface();
}
