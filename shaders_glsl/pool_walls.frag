#version 450
#extension GL_GOOGLE_include_directive : require
// The pool's walls (plain or brick, shared/pool.h), Lambertian (shared/shading.h), through the water when the camera is under it.
#include "shared/shading.h"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(binding = 3) uniform Medium { CameraMedium medium; };

void main() {
  const vec3 n = normalize(worldNormal);
  const vec3 toCamera = viewTransmittance(medium, frame.cameraPosition.xyz, worldPosition);
  const vec2 footprint = fwidth(poolWallCoordinates(pool, worldPosition, n));
  color = vec4(poolWallRadiance(pool, frame, worldPosition, n, footprint) * toCamera, 1.0);
  writeGbuffer(frame, n, poolWallRadiance(pool, withoutSun(frame), worldPosition, n, footprint) * toCamera);
}
