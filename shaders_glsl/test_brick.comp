#version 450
#extension GL_GOOGLE_include_directive : require
// Test-only: the pool walls' albedo (shared/pool.h: bricks, tones, dirt) at
// wall points, so the tests can compare the GPU's values with the CPU's.
#include "shared/pool.h"

layout(local_size_x = 64) in;
layout(binding = 0) readonly buffer Points { vec2 points[]; };
layout(binding = 1) writeonly buffer Values { vec4 values[]; };
layout(binding = 2) uniform Pool { PoolParams pool; };
layout(push_constant) uniform Push { uint count; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  values[i] = vec4(poolWallAlbedo(pool, points[i], vec2(0.0)), 0.0);
}
