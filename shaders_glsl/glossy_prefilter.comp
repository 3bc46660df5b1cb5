#version 450
#extension GL_GOOGLE_include_directive : require
// One level of the glossy environment map (shared/glossy.h): for each texel's
// direction r, G(r) = the environment convolved with the normalised Phong
// lobe of the level's exponent about r, estimated from samples.x directions
// drawn from the environment's luminance (the CDFs of env_rows.comp and
// env_marginal.comp) and samples.y drawn from the lobe, combined by the
// balance heuristic (multiple importance sampling): each sample weighs
// L f / (n_env p_env + n_lobe p_lobe). Either count may be 0. The
// environment is piecewise constant (texelFetch), as the sampler's density
// assumes. Each texel rotates the Hammersley sets by its own hash (fixed:
// the same bits every run).
#include "shared/env_sampling.h"
#include "shared/glossy.h"
#include "shared/noise.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D environment;
layout(binding = 1) readonly buffer Conditional { float conditional[]; };
layout(binding = 2) readonly buffer Marginal { float marginal[]; };
layout(binding = 3, rgba16f) uniform writeonly image2D level;
layout(push_constant) uniform Push { GlossyParams params; };

#include "lib/env_cdf.glsl"

void main() {
  const uvec2 texel = gl_GlobalInvocationID.xy, size = params.size.zw, envSize = params.size.xy;
  if (texel.x >= size.x || texel.y >= size.y) return;
  const vec3 r = equirectToDirection((vec2(texel) + 0.5) / vec2(size));
  const float e = params.lobe.x;
  const uint nEnv = params.samples.x, nLobe = params.samples.y;
  const float total = marginal[envSize.y + 1u];  // the luminance's integral: p_env = lum / total
  const uint seed = hashCell(int(texel.x), int(texel.y), params.samples.z);
  const vec2 rotation = vec2(float(hashUint(seed) >> 8u), float(hashUint(seed + 1u) >> 8u)) * (1.0 / 16777216.0);
  vec3 sum = vec3(0.0);
  if (total > 0.0) {
    for (uint k = 0u; k < nEnv; ++k) {
      const vec4 drawn = envDrawTexel(envHammersley(k, nEnv, rotation), envSize);
      const vec3 d = envTexelDirection(uvec2(drawn.xy), drawn.zw, envSize);
      const vec3 radiance = texelFetch(environment, ivec2(drawn.xy), 0).rgb;
      const float f = glossyLobe(e, dot(d, r));
      const float pdfs = float(nEnv) * envLuminance(radiance) / total + float(nLobe) * f;
      if (pdfs > 0.0) sum += radiance * (f / pdfs);
    }
  }
  for (uint k = 0u; k < nLobe; ++k) {
    const vec3 d = glossyLobeDirection(r, e, envHammersley(k, nLobe, rotation.yx));
    const vec3 radiance = texelFetch(environment, ivec2(envTexelOf(d, envSize)), 0).rgb;
    const float f = glossyLobe(e, dot(d, r));
    const float pEnv = total > 0.0 ? envLuminance(radiance) / total : 0.0;
    const float pdfs = float(nEnv) * pEnv + float(nLobe) * f;
    if (pdfs > 0.0) sum += radiance * (f / pdfs);
  }
  imageStore(level, ivec2(texel), vec4(sum, 1.0));
}
