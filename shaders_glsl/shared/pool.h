// The pool: a square hole in the ground, its inner walls, and a tiled floor
// shaped by value-noise terrain. A uniform buffer filled once per scene
// (render/pool_model.cpp); the floor's height function is shared with C++.
#ifndef TP_SHARED_POOL_H
#define TP_SHARED_POOL_H
#include "shared/ground.h"
#include "shared/interop.h"
#include "shared/noise.h"

TP_BEGIN

struct PoolParams {
  vec4 box;         // x: half size of the square pool, y: rim height, z: mean floor depth below the rim, w: terrain amplitude
  vec4 terrain;     // x: terrain frequency (1/m), y: persistence; zw unused
  uvec4 noise;      // x: octaves, y: seed, z: ray-march steps, w: bisection steps
  vec4 wallAlbedo;  // rgb
  GroundParams tiles;  // the floor's checker: plane.z tile size, albedoA, albedoB
};

// Height of the pool floor at world xz: the mean floor plus the terrain, a
// fractal sum of bilinear value noise normalised to [-amplitude/2, amplitude/2].
TP_INLINE float poolFloorHeight(PoolParams p, vec2 xz) {
  TP_PRECISE float total = 0.0f;
  TP_PRECISE float amplitude = 1.0f;
  for (uint i = 0u; i < p.noise.x; ++i) {
    total += amplitude;
    amplitude *= p.terrain.y;
  }
  TP_PRECISE float f = fractalNoise(TP_NOISE_VALUE_BILINEAR, xz * p.terrain.x, p.noise.y, p.noise.x, p.terrain.y);
  TP_PRECISE float h = p.box.y - p.box.z + p.box.w * (f / total - 0.5f);
  return h;
}

// The lowest the floor can be: where the walls end.
TP_INLINE float poolBottom(PoolParams p) { return p.box.y - p.box.z - 0.5f * p.box.w; }

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::PoolParams) == 112);
#endif

#endif
