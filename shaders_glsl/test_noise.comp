#version 450
#extension GL_GOOGLE_include_directive : require
// Test-only: evaluates the shared noise at sample points, so the tests can
// compare the GPU's values with the CPU's (shared/noise.h).
#include "shared/noise.h"

layout(local_size_x = 64) in;
layout(binding = 0) readonly buffer Points { vec2 points[]; };
layout(binding = 1) writeonly buffer Values { float values[]; };
layout(push_constant) uniform Push { NoiseSampleParams params; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.count) return;
  values[i] = params.normalised != 0u
                  ? fractalNoise01(params.kind, points[i], params.seed, params.octaves, params.persistence)
                  : fractalNoise(params.kind, points[i], params.seed, params.octaves, params.persistence);
}
