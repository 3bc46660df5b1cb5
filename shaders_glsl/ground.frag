#version 450
#extension GL_GOOGLE_include_directive : require
// The ground plane and its pattern (shared/shading.h): never in the pool,
// so its sun shadows are those of the open air.
#include "shared/shading.h"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
layout(push_constant) uniform Push { GroundParams ground; };

void main() {
  // The ground is level: a constant normal, which the compiler folds into
  // the sky's irradiance and the sun's cosine (evaluated per pixel from an
  // interpolated normal they cost a sixth of the pass; the same bits).
  const vec3 n = vec3(0.0, 1.0, 0.0);
  const vec2 footprint = fwidth(worldPosition.xz) * frame.sampling.x;
  // The pattern once, for the colour and the ambient part alike.
  const vec3 albedo = groundAlbedo(ground, worldPosition.xz, footprint);
  color = vec4(lambertRadiance(frame, albedo, n, frameOpenAirSunShare(worldPosition)), 1.0);
  writeGbuffer(frame, n, lambertRadiance(withoutSun(frame), albedo, n, 1.0));
}
