// What SSAO needs of each opaque surface, written beside its colour by the
// surface's own pass: its view-space normal, and the part of its radiance the
// sky's ambient light makes (its radiance with the sun taken away), which AO
// then scales (ao_apply.comp). Frames without AO draw with the colour-only
// variant (TP_COLOR_ONLY, cmake/shaders.cmake), which has neither output.
#ifndef TP_LIB_GBUFFER
#define TP_LIB_GBUFFER
#include "shared/frame.h"

#ifndef TP_COLOR_ONLY
layout(location = 1) out vec4 gbufferNormal;
layout(location = 2) out vec4 gbufferAmbient;
#endif

FrameUniforms withoutSun(FrameUniforms frame) {
  frame.sunIrradiance = vec4(0.0);
  return frame;
}

void writeGbuffer(FrameUniforms frame, vec3 worldNormal, vec3 ambientRadiance) {
#ifndef TP_COLOR_ONLY
  gbufferNormal = vec4(normalize(mat3(frame.view) * worldNormal), 0.0);
  gbufferAmbient = vec4(ambientRadiance, 0.0);
#endif
}

// Where no surface is (the sky): what the surfaces' first pass clears the
// G-buffer to, written by a pass that draws over that clear.
void writeNoSurface() {
#ifndef TP_COLOR_ONLY
  gbufferNormal = vec4(0.0);
  gbufferAmbient = vec4(0.0);
#endif
}

#endif
