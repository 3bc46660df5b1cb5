#version 450
#extension GL_GOOGLE_include_directive : require
// A Lambertian sphere (shared/shading.h) with its glossy lobe (shared/glossy.h)
// lit by its probe, through the water when the camera is under it.
#include "shared/shading.h"
#include "shared/water.h"
#include "shared/objects.h"
#include "lib/gbuffer.glsl"
#include "lib/glossy_lookup.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform Medium { CameraMedium medium; };
layout(binding = 2) uniform sampler2D glossyMap;  // the sphere's probe (render/glossy_probes), or the sky's
layout(binding = 3) uniform Pool { PoolParams pool; };
layout(binding = 4) uniform sampler2D caustics;  // the sun through the waves, for the parts under the water
layout(binding = 5) readonly buffer WaterCells { WaterCell waterCells[]; };  // the simulation's state
layout(binding = 6) readonly buffer FloorVertices { vec4 floorVertices[]; };  // and the pool's baked light
#include "shared/pool_light.h"
#include "lib/sun_through_waves.glsl"  // reads `waterCells` in place
layout(push_constant) uniform Push { SphereParams params; };

void main() {
  const vec3 n = normalize(worldNormal);
  const vec3 toCamera = viewTransmittance(medium, frame.cameraPosition.xyz, worldPosition);
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  const float caustic = sunThroughWaves(caustics, pool, frame.sunDirection.xyz, worldPosition);
  const vec3 diffuse =
      params.albedo.rgb / kPi * objectIrradiance(pool, frame, worldPosition, n, frameSunShare(worldPosition) * caustic);
  color = vec4(glossyProbeRadiance(glossyMap, pool, params.sphere, worldPosition, diffuse, view, n,
                                   params.material.xy) *
                       toCamera +
                   viewInScatter(medium, poolLightAround(pool, 0.5 * (frame.cameraPosition.xyz + worldPosition)), worldPosition),
               1.0);
  // AO scales the Lambertian part's light but the sun's.
  writeGbuffer(frame, n, glossyMix(params.albedo.rgb / kPi * objectIrradiance(pool, frame, worldPosition, n, 0.0),
                                   vec3(0.0), params.material.x) * toCamera);
}
