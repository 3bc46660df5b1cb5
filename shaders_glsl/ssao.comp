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
layout(binding = 5, r32f) uniform writeonly image2D viewDepthImage;  // aoViewDepth, for the passes after
layout(push_constant) uniform Push { SsaoParams params; };

vec3 viewPositionAt(ivec2 q, vec2 frameSize) {
  return viewPositionFromDepth(frame.inverseProjection, (vec2(q) + 0.5) / frameSize, texelFetch(depthTexture, q, 0).r);
}

// The scene's view-space z seen at texture coordinate uv. Nearest (the
// original's): the depth of the pixel uv falls in, which on a surface seen at
// a grazing angle lies far nearer or farther than the sample, and a flat
// ground then occludes itself. Interpolated: the depth buffer bilinearly
// interpolated at uv, exact on any plane (depth is affine in screen space);
// by hand, as depth formats need not filter linearly, from one gather of the
// four texels (a quarter less time for the pass on lavapipe than four
// fetches; the same texels, clamped at the edges by the sampler).
float sceneViewZ(vec2 uv, vec2 frameSize) {
  if (params.config.w == 0u) return viewPositionAt(ivec2(uv * frameSize), frameSize).z;
  const vec2 at = uv * frameSize - 0.5;
  const ivec2 q = ivec2(floor(at));
  const vec2 t = at - vec2(q);
  // At q + 1 the footprint's corner is q, half a texel from either side.
  const vec4 g = textureGather(depthTexture, (vec2(q) + 1.0) / frameSize, 0);
  const float d00 = g.w, d10 = g.z, d01 = g.x, d11 = g.y;  // gather's order: (0,1) (1,1) (1,0) (0,0)
  const float depth = mix(mix(d00, d10, t.x), mix(d01, d11, t.x), t.y);
  return viewPositionFromDepth(frame.inverseProjection, uv, depth).z;
}

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(params.size.xy)))) return;
  const ivec2 d = p * int(params.config.z);  // the frame pixel this AO pixel stands for
  const vec2 frameSize = vec2(params.size.zw);
  const float depth = texelFetch(depthTexture, d, 0).r;
  imageStore(viewDepthImage, p, vec4(aoViewDepth(frame.inverseProjection, depth)));
  if (depth >= 1.0) {  // no surface: nothing to occlude
    imageStore(aoImage, p, vec4(1.0));
    return;
  }
  const vec3 origin = viewPositionAt(d, frameSize);
  const vec3 n = normalize(imageLoad(normalImage, d).xyz);
  const int tile = int(params.config.y);
  const vec3 random = vec3(kernel.noise[(p.y % tile) * tile + p.x % tile].xy, 0.0);
  // Gram-Schmidt; a random vector (nearly) along the normal leaves no
  // tangent, and then any perpendicular serves.
  vec3 tangent = random - n * dot(random, n);
  if (dot(tangent, tangent) <= 1e-6 * dot(random, random)) {  // also a zero random vector
    tangent = cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
  }
  tangent = normalize(tangent);
  const mat3 tbn = mat3(tangent, cross(n, tangent), n);
  const float radius = params.shape.x, bias = params.shape.y;
  float occluded = 0.0;
  for (uint i = 0u; i < params.config.x; ++i) {
    const vec3 s = origin + radius * (tbn * kernel.samples[i].xyz);
    const vec4 clip = frame.projection * vec4(s, 1.0);
    const vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;  // off screen: no evidence
    const float sceneZ = sceneViewZ(uv, frameSize);
    const float range = smoothstep(0.0, 1.0, radius / abs(origin.z - sceneZ));
    occluded += (sceneZ >= s.z + bias ? 1.0 : 0.0) * range;
  }
  imageStore(aoImage, p, vec4(1.0 - occluded / float(params.config.x)));
}
