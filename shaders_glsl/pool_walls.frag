#version 450
#extension GL_GOOGLE_include_directive : require
// The pool's walls (plain or brick, shared/pool.h), Lambertian (shared/shading.h)
// with their glossy lobe (shared/glossy.h) lit by the pool's probe above the water,
// through the water when the camera is under it.
#include "shared/shading.h"
#include "shared/water.h"
#include "lib/gbuffer.glsl"
#include "lib/glossy_lookup.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
#include "shared/sun_shadow.h"  // reads `frame` in place
#include "shared/water_scattering.h"  // reads `frame` in place
layout(binding = 1) uniform Pool { PoolParams pool; };
layout(binding = 2) uniform sampler2D caustics;
layout(binding = 6) readonly buffer WaterCells { WaterCell waterCells[]; };  // the simulation's state
#include "lib/sun_through_waves.glsl"  // reads `waterCells` in place
layout(binding = 3) uniform Medium { CameraMedium medium; };
layout(binding = 4) uniform sampler2D glossyMap;
layout(binding = 7) uniform sampler2D poolProbe;  // the pool's probe (render/glossy_probes), or the sky's map
layout(binding = 5) readonly buffer FloorVertices { vec4 floorVertices[]; };  // and the baked light
#include "shared/pool_light.h"

void main() {
  const vec3 n = normalize(worldNormal);
  const vec3 toCamera = viewTransmittance(medium, frame.cameraPosition.xyz, worldPosition);
  const vec2 footprint = fwidth(poolWallCoordinates(pool, worldPosition, n)) * frame.sampling.x;
  const vec3 view = normalize(worldPosition - frame.cameraPosition.xyz);
  // Under the water the sun comes through the waves (the caustics texture).
  const float caustic = sunThroughWaves(caustics, pool, frame.sunDirection.xyz, worldPosition);
  const vec3 albedo = poolWallAlbedo(pool, poolWallCoordinates(pool, worldPosition, n), footprint);
  const vec3 diffuse = albedo / kPi * poolIrradiance(pool, frame, worldPosition, n, frameSunShare(worldPosition) * caustic);
  color = vec4(glossyWallRadiance(poolProbe, glossyMap, pool, worldPosition, diffuse, view, n, pool.wallGloss.xy) *
                       toCamera +
                   viewInScatter(medium, poolLightAround(pool, 0.5 * (frame.cameraPosition.xyz + worldPosition)), worldPosition),
               1.0);
  // AO scales the Lambertian part's light but the sun's.
  writeGbuffer(frame, n, glossyMix(albedo / kPi * poolIrradiance(pool, frame, worldPosition, n, 0.0), vec3(0.0),
                                   pool.wallGloss.x) * toCamera);
}
