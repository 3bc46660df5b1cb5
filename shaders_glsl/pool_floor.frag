#version 450
#extension GL_GOOGLE_include_directive : require
// The tiled pool floor, Lambertian (shared/shading.h), lit through the water
// (the sun through the waves from the caustics texture, the rest baked:
// shared/pool_light.h), seen through the water when the camera is under it.
#include "shared/shading.h"
#include "lib/caustics_lookup.glsl"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(binding = 2) uniform sampler2D caustics;
layout(binding = 3) uniform Medium { CameraMedium medium; };
layout(binding = 5) readonly buffer FloorVertices { vec4 floorVertices[]; };  // and the baked light
#include "shared/pool_light.h"

void main() {
  const vec3 n = normalize(worldNormal);
  const vec2 footprint = fwidth(worldPosition.xz) * frame.sampling.x;
  const float caustic =
      causticsRatio(caustics, pool, frame.sunDirection.xyz, worldPosition) * frameSunShare(worldPosition);
  const vec3 toCamera = viewTransmittance(medium, frame.cameraPosition.xyz, worldPosition);
  const vec3 albedo = groundAlbedo(pool.tiles, worldPosition.xz, footprint);
  color = vec4(albedo / kPi * poolIrradiance(pool, frame, worldPosition, n, caustic) * toCamera +
                   viewInScatter(medium, poolLightAround(pool, 0.5 * (frame.cameraPosition.xyz + worldPosition)), worldPosition),
               1.0);
  writeGbuffer(frame, n, albedo / kPi * poolIrradiance(pool, frame, worldPosition, n, 0.0) * toCamera);
}
