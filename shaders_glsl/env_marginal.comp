#version 450
#extension GL_GOOGLE_include_directive : require
// The environment sampler's marginal CDF over the rows, from env_rows.comp's
// row weights: one invocation (a running sum over at most a few thousand
// rows), normalised to end at 1; entry height + 1 holds the luminance's
// integral over the sphere, the sampler's normalisation.
#include "shared/env_sampling.h"

layout(local_size_x = 1) in;
layout(binding = 0) readonly buffer RowWeights { float rowWeight[]; };
layout(binding = 1) buffer Marginal { float marginal[]; };  // height + 2 entries
layout(push_constant) uniform Push { EnvParams params; };

void main() {
  const uint h = params.size.y;
  float sum = 0.0;
  marginal[0] = 0.0;
  for (uint j = 0u; j < h; ++j) {
    sum += rowWeight[j];
    marginal[j + 1u] = sum;
  }
  if (sum > 0.0) {
    for (uint j = 1u; j <= h; ++j) marginal[j] /= sum;
  }
  marginal[h + 1u] = sum;
}
