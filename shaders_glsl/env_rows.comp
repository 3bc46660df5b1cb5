#version 450
#extension GL_GOOGLE_include_directive : require
// The environment sampler's conditional CDFs (shared/env_sampling.h): one
// invocation per row, a running sum of the luminance along it, normalised
// to end at 1 (a row of no light stays all 0); and the row's weight, its
// luminance sum times one texel's solid angle, for env_marginal.comp.
#include "shared/env_sampling.h"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D environment;
layout(binding = 1) buffer Conditional { float conditional[]; };  // per row: width + 1 entries
layout(binding = 2) writeonly buffer RowWeights { float rowWeight[]; };
layout(push_constant) uniform Push { EnvParams params; };

void main() {
  const uint j = gl_GlobalInvocationID.x, w = params.size.x, h = params.size.y;
  if (j >= h) return;
  const uint base = j * (w + 1u);
  float sum = 0.0;
  conditional[base] = 0.0;
  for (uint i = 0u; i < w; ++i) {
    sum += max(envLuminance(texelFetch(environment, ivec2(i, j), 0).rgb), 0.0);
    conditional[base + i + 1u] = sum;
  }
  if (sum > 0.0) {
    for (uint i = 1u; i <= w; ++i) conditional[base + i] /= sum;
  }
  rowWeight[j] = sum * envTexelSolidAngle(j, w, h);
}
