#version 450
#extension GL_GOOGLE_include_directive : require
// Screen-space ambient occlusion (the original's, after LearnOpenGL): each
// pixel's view-space position from the depth buffer and the inverse
// projection, a TBN from its normal and the noise tile's rotation vector by
// Gram-Schmidt, and the kernel's hemisphere samples projected and compared
// with the depth buffer (a bias, and a smoothstep range check that ignores
// occluders far beyond the radius). AO = 1 - occluded / kernel size.
#include "shared/frame.h"
#include "shared/ssao.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D depthTexture;
layout(binding = 2, rgba16f) uniform readonly image2D normalImage;
layout(binding = 3) uniform Kernel { SsaoKernel kernel; };
layout(binding = 4, r32f) uniform writeonly image2D aoImage;
layout(push_constant) uniform Push { SsaoParams params; };

vec3 viewPosition(vec2 uv, float depth) {
  const vec4 p = frame.inverseProjection * vec4(uv * 2.0 - 1.0, depth, 1.0);
  return p.xyz / p.w;
}

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 size = ivec2(params.config.zw);
  if (any(greaterThanEqual(p, size))) return;
  const float depth = texelFetch(depthTexture, p, 0).r;
  if (depth >= 1.0) {  // no surface: nothing to occlude
    imageStore(aoImage, p, vec4(1.0));
    return;
  }
  const vec3 origin = viewPosition((vec2(p) + 0.5) / vec2(size), depth);
  const vec3 n = normalize(imageLoad(normalImage, p).xyz);
  const int tile = int(params.config.y);
  const vec3 random = vec3(kernel.noise[(p.y % tile) * tile + p.x % tile].xy, 0.0);
  // Gram-Schmidt; a random vector (nearly) along the normal leaves no
  // tangent, and then any perpendicular serves.
  vec3 tangent = random - n * dot(random, n);
  if (dot(tangent, tangent) < 1e-6) tangent = cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
  tangent = normalize(tangent);
  const mat3 tbn = mat3(tangent, cross(n, tangent), n);
  const float radius = params.shape.x, bias = params.shape.y;
  float occluded = 0.0;
  for (uint i = 0u; i < params.config.x; ++i) {
    const vec3 s = origin + radius * (tbn * kernel.samples[i].xyz);
    const vec4 clip = frame.projection * vec4(s, 1.0);
    const vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;  // off screen: no evidence
    const ivec2 q = ivec2(uv * vec2(size));
    const float sceneZ = viewPosition((vec2(q) + 0.5) / vec2(size), texelFetch(depthTexture, q, 0).r).z;
    const float range = smoothstep(0.0, 1.0, radius / abs(origin.z - sceneZ));
    occluded += (sceneZ >= s.z + bias ? 1.0 : 0.0) * range;
  }
  imageStore(aoImage, p, vec4(1.0 - occluded / float(params.config.x)));
}
