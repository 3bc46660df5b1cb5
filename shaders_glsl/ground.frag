#version 450
#extension GL_GOOGLE_include_directive : require
// The ground plane and its pattern (shared/shading.h): never in the pool,
// so its sun shadows are those of the open air.
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
  // The pattern once, for the colour and the ambient part alike.
  const vec3 albedo = groundAlbedo(ground, worldPosition.xz, footprint);
  color = vec4(lambertRadiance(frame, albedo, n, frameOpenAirSunShare(worldPosition)), 1.0);
  writeGbuffer(frame, n, lambertRadiance(withoutSun(frame), albedo, n, 1.0));
}
