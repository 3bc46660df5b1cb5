#version 450
#extension GL_GOOGLE_include_directive : require
// Caustics, after Evan Wallace's WebGL Water: each vertex of the water grid
// reaching the walls (lib/water_grid.glsl) sends the sun's ray, refracted by
// its normal, down to where it meets the pool (a wall, or the floor: a level
// plane at the floor's height near the landing), and is drawn in a texture
// over the pool's square at that point's light line (shared/shading.h's
// causticsLine: where the flat water's refracted sun line through it crosses
// the rest level); it also carries its light line through flat water, its own
// place at rest. The fragment stage compares the two areas. The floor, the walls and the objects under the
// water read the texture at their own light lines.
#include "shared/frame.h"
#include "shared/shading.h"
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
  const vec3 toSun = frame.sunDirection.xyz;
  const vec3 waveRay = refract(-toSun, wallGridNormal(gl_VertexIndex), 1.0 / surface.extinction.w);
  const vec3 p = wallGridPosition(gl_VertexIndex, 1.0);
  // The floor as the level plane at its height where the ray meets the mean
  // floor's plane: the foci lie on the floor's relief, not on its mean (a
  // second such step gains nothing measurable); or a wall, if nearer.
  const float floorY = poolFloorHeight(pool, land(p, waveRay, pool.box.y - pool.box.z));
  const vec2 walls = poolWallDistances(pool, p, waveRay);
  const float reach = min(min(walls.x, walls.y), (p.y - floorY) / max(-waveRay.y, 1e-6));
  flatLanding = wallGridPosition(gl_VertexIndex, 0.0).xz;
  landing = causticsLine(pool, toSun, p + reach * waveRay);
  gl_Position = vec4(landing / pool.box.x, 0.0, 1.0);
}
