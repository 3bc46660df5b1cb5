#version 450
#extension GL_GOOGLE_include_directive : require
// Caustics, as in Evan Wallace's WebGL Water: each vertex of the water grid
// sends the sun's ray, refracted by its normal, down to the floor (a level
// plane at the floor's height near where it lands), and is drawn where it
// lands in a texture over the pool's square; it also carries where the ray
// would land through flat water. The fragment stage compares the two areas.
#include "shared/frame.h"
#include "shared/pool.h"
#include "lib/water_grid.glsl"

layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 3) uniform Pool { PoolParams pool; };
layout(location = 0) out vec2 flatLanding;
layout(location = 1) out vec2 landing;

// Where the ray from p along d meets the plane y = floorY (d going down).
vec2 land(vec3 p, vec3 d, float floorY) {
  return p.xz + d.xz * (p.y - floorY) / max(-d.y, 1e-6);
}

void main() {
  const vec3 sunRay = -frame.sunDirection.xyz;
  const float eta = 1.0 / surface.extinction.w;
  const vec3 flatRay = refract(sunRay, vec3(0.0, 1.0, 0.0), eta);
  const vec3 waveRay = refract(sunRay, gridNormal(gl_VertexIndex), eta);
  // Both rays land on the level plane through the floor where the wave's ray
  // meets the mean floor's plane: the foci lie on the floor's relief, not on
  // its mean (a second such step gains nothing measurable).
  const vec3 p = gridPosition(gl_VertexIndex, 1.0);
  const float floorY = poolFloorHeight(pool, land(p, waveRay, pool.box.y - pool.box.z));
  flatLanding = land(gridPosition(gl_VertexIndex, 0.0), flatRay, floorY);
  landing = land(p, waveRay, floorY);
  gl_Position = vec4(landing / pool.box.x, 0.0, 1.0);
}
