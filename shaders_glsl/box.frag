#version 450
#extension GL_GOOGLE_include_directive : require
// A Lambertian box (shared/shading.h), through the water when the camera is under it.
#include "shared/shading.h"
#include "shared/water.h"
#include "shared/objects.h"
#include "lib/gbuffer.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform Medium { CameraMedium medium; };
layout(binding = 3) uniform Pool { PoolParams pool; };
layout(binding = 4) uniform sampler2D caustics;  // the sun through the waves, for the parts under the water
layout(binding = 5) readonly buffer WaterCells { WaterCell waterCells[]; };  // the simulation's state
layout(binding = 6) readonly buffer FloorVertices { vec4 floorVertices[]; };  // and the pool's baked light
#include "shared/pool_light.h"
#include "lib/sun_through_waves.glsl"  // reads `waterCells` in place
layout(push_constant) uniform Push { BoxParams params; };

void main() {
  const vec3 n = normalize(worldNormal);
  const vec3 toCamera = viewTransmittance(medium, frame.cameraPosition.xyz, worldPosition);
  const float caustic = sunThroughWaves(caustics, pool, frame.sunDirection.xyz, worldPosition);
  const vec3 reflectance = params.albedo.rgb / kPi;
  color = vec4(reflectance * objectIrradiance(pool, frame, worldPosition, n, frameSunShare(worldPosition) * caustic) *
                       toCamera +
                   viewInScatter(medium, poolLightAround(pool, 0.5 * (frame.cameraPosition.xyz + worldPosition)), worldPosition),
               1.0);
  writeGbuffer(frame, n, reflectance * objectIrradiance(pool, frame, worldPosition, n, 0.0) * toCamera);
}
