#version 450
#extension GL_GOOGLE_include_directive : require
// Test-only: the ground's and the pool's patterns (shared/surface_pattern.h,
// shared/pool.h) at points and footprints, so the tests can compare the
// GPU's values with the CPU's.
#include "shared/pool.h"

layout(local_size_x = 64) in;
// xy: the point in metres, zw: the footprint.
layout(binding = 0) readonly buffer Points { vec4 points[]; };
// Per point: the ground's albedo, the floor's, the walls'.
layout(binding = 1) writeonly buffer Values { vec4 values[]; };
layout(binding = 2) uniform Pool { PoolParams pool; };
layout(push_constant) uniform Push { uint count; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  const vec2 p = points[i].xy, footprint = points[i].zw;
  values[3 * i] = vec4(groundAlbedo(pool.ground, p, footprint), 0.0);
  values[3 * i + 1] = vec4(groundAlbedo(pool.tiles, p, footprint), 0.0);
  values[3 * i + 2] = vec4(poolWallAlbedo(pool, p, footprint), 0.0);
}
