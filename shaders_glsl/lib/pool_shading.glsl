// The exact cast of a ray from inside the pool against its walls and floor
// (the refracted rays of the water surface); shading is in shared/shading.h.
#ifndef TP_LIB_POOL_SHADING
#define TP_LIB_POOL_SHADING
#include "shared/pool.h"
#include "shared/shading.h"

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
      return PoolHit(hi, hit, poolFloorNormal(pool, hit.xz, kPoolFloorNormalSpacing), true);
    }
    previous = s;
  }
  vec3 wallPoint = origin + sWall * dir;
  vec3 normal = sx < sz ? vec3(-sign(dir.x), 0.0, 0.0) : vec3(0.0, 0.0, -sign(dir.z));
  return PoolHit(sWall, wallPoint, normal, false);
}

#endif
