// Shading of the pool's walls and floor, and the exact cast of a ray from
// inside the pool against them (the refracted rays of the water surface).
#ifndef TP_LIB_POOL_SHADING
#define TP_LIB_POOL_SHADING
#include "lib/ground_shading.glsl"
#include "shared/pool.h"

// Floor normal from central differences of the height function; `spacing` is
// the finite-difference step in metres.
vec3 poolFloorNormal(PoolParams pool, vec2 xz, float spacing) {
  float dx = poolFloorHeight(pool, xz + vec2(spacing, 0.0)) - poolFloorHeight(pool, xz - vec2(spacing, 0.0));
  float dz = poolFloorHeight(pool, xz + vec2(0.0, spacing)) - poolFloorHeight(pool, xz - vec2(0.0, spacing));
  return normalize(vec3(-dx, 2.0 * spacing, -dz));
}

vec3 poolFloorRadiance(PoolParams pool, FrameUniforms frame, vec3 position, vec3 normal, vec2 footprint) {
  return groundRadiance(pool.tiles, frame, position.xz, footprint, normal);
}

vec3 poolWallRadiance(PoolParams pool, FrameUniforms frame, vec3 normal) {
  vec3 irradiance = frame.sunIrradiance.rgb * max(dot(normal, frame.sunDirection.xyz), 0.0) + 0.5 * frame.skyIrradiance.rgb;
  return pool.wallAlbedo.rgb / GROUND_PI * irradiance;
}

struct PoolHit {
  float distance;
  vec3 position;
  vec3 normal;
  bool floor;
};

// The first wall or floor point along origin + s dir (origin inside the pool,
// dir going down): the walls analytically, the floor by marching the height
// field in noise.z steps up to the walls and bisecting noise.w times.
PoolHit tracePool(PoolParams pool, vec3 origin, vec3 dir) {
  const float halfSize = pool.box.x;
  float sx = dir.x > 0.0 ? (halfSize - origin.x) / dir.x : (dir.x < 0.0 ? (-halfSize - origin.x) / dir.x : 1e30);
  float sz = dir.z > 0.0 ? (halfSize - origin.z) / dir.z : (dir.z < 0.0 ? (-halfSize - origin.z) / dir.z : 1e30);
  float sWall = max(min(sx, sz), 0.0);
  float sBottom = dir.y < 0.0 ? (poolBottom(pool) - origin.y) / dir.y : 1e30;
  float sEnd = min(sWall, sBottom);
  float previous = 0.0;
  for (uint i = 1u; i <= pool.noise.z; ++i) {
    float s = sEnd * float(i) / float(pool.noise.z);
    vec3 p = origin + s * dir;
    if (p.y <= poolFloorHeight(pool, p.xz)) {
      float lo = previous, hi = s;
      for (uint k = 0u; k < pool.noise.w; ++k) {
        float mid = 0.5 * (lo + hi);
        vec3 m = origin + mid * dir;
        if (m.y <= poolFloorHeight(pool, m.xz)) hi = mid; else lo = mid;
      }
      vec3 hit = origin + hi * dir;
      return PoolHit(hi, hit, poolFloorNormal(pool, hit.xz, 0.01), true);
    }
    previous = s;
  }
  vec3 wallPoint = origin + sWall * dir;
  vec3 normal = sx < sz ? vec3(-sign(dir.x), 0.0, 0.0) : vec3(0.0, 0.0, -sign(dir.z));
  return PoolHit(sWall, wallPoint, normal, false);
}

#endif
