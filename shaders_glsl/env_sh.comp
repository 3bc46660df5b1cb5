#version 450
#extension GL_GOOGLE_include_directive : require
// The environment's SH9 coefficients estimated from `samples` directions of
// the rotated Hammersley set: drawn by the luminance (the CDFs of
// env_rows.comp and env_marginal.comp, inverted by binary search) or
// uniformly over the sphere, each weighted by radiance / density. One
// partial per workgroup (a tree reduction in shared memory); the host adds
// the partials in double.
#include "shared/env_sampling.h"
#include "shared/sh9.h"

layout(local_size_x = 64) in;
const uint GROUP = 64;
layout(binding = 0) uniform sampler2D environment;
layout(binding = 1) readonly buffer Conditional { float conditional[]; };
layout(binding = 2) readonly buffer Marginal { float marginal[]; };
layout(binding = 3) writeonly buffer Partials { vec4 partials[]; };  // 9 per workgroup
layout(push_constant) uniform Push { EnvParams params; };

shared vec3 sSh[9 * GROUP];

#include "lib/env_cdf.glsl"

void main() {
  const uint k = gl_GlobalInvocationID.x, t = gl_LocalInvocationIndex;
  const uint w = params.size.x, h = params.size.y, n = params.size.z;
  for (uint i = 0u; i < 9u; ++i) sSh[i * GROUP + t] = vec3(0.0);
  if (k < n) {
    const vec2 xi = envHammersley(k, n, params.rotation.xy);
    vec3 d, radiance;
    float pdf;
    if (params.size.w == 1u) {
      d = envUniformDirection(xi);
      const vec2 uv = directionToEquirect(d);
      const ivec2 texel = min(ivec2(uv * vec2(w, h)), ivec2(w, h) - 1);
      radiance = texelFetch(environment, texel, 0).rgb;
      pdf = 1.0 / (4.0 * kPi);
    } else {
      const vec4 drawn = envDrawTexel(xi, uvec2(w, h));
      const uvec2 texel = uvec2(drawn.xy);
      d = envTexelDirection(texel, drawn.zw, uvec2(w, h));
      radiance = texelFetch(environment, ivec2(texel), 0).rgb;
      pdf = envLuminance(radiance) / marginal[h + 1u];
    }
    const vec3 weight = radiance / pdf;
    for (uint i = 0u; i < 9u; ++i) sSh[i * GROUP + t] = weight * sh9Basis(i, d);
  }
  for (uint stride = GROUP / 2u; stride > 0u; stride /= 2u) {
    barrier();
    if (t < stride) {
      for (uint i = 0u; i < 9u; ++i) sSh[i * GROUP + t] += sSh[i * GROUP + t + stride];
    }
  }
  barrier();
  if (t < 9u) partials[gl_WorkGroupID.x * 9u + t] = vec4(sSh[t * GROUP], 0.0);
}
