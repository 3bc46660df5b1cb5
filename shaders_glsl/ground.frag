#version 450
#extension GL_GOOGLE_include_directive : require
// The checkered ground plane (shared/shading.h).
#include "shared/shading.h"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
layout(push_constant) uniform Push { GroundParams ground; };

void main() {
  const vec3 n = normalize(worldNormal);
  const vec2 footprint = fwidth(worldPosition.xz) * frame.sampling.x;
  color = vec4(groundRadiance(ground, frame, worldPosition.xz, footprint, n, frameSunShare(worldPosition)), 1.0);
  writeGbuffer(frame, n, groundRadiance(ground, withoutSun(frame), worldPosition.xz, footprint, n, 1.0));
}
