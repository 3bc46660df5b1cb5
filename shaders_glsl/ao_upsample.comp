#version 450
#extension GL_GOOGLE_include_directive : require
// Half-resolution AO to the frame, depth aware (a joint bilateral upsample):
// each frame pixel blends the four AO pixels around it with bilinear weights,
// keeping only those whose surface lies at about its own view depth, so that
// AO does not leak across silhouettes; where none does, the nearest in depth.
#include "shared/frame.h"
#include "shared/ssao.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D depthTexture;
layout(binding = 2, r32f) uniform readonly image2D source;
layout(binding = 3, r32f) uniform writeonly image2D target;
layout(push_constant) uniform Push { AoUpsampleParams params; };

float viewDepthAt(ivec2 framePixel) {
  return -viewPositionFromDepth(frame.inverseProjection, vec2(0.5), texelFetch(depthTexture, framePixel, 0).r).z;
}

void main() {
  const ivec2 f = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(f, ivec2(params.size.xy)))) return;
  if (texelFetch(depthTexture, f, 0).r >= 1.0) {
    imageStore(target, f, vec4(1.0));
    return;
  }
  const int factor = int(params.shape.y);
  const ivec2 lowSize = ivec2(params.size.zw);
  // AO pixel q stands for frame pixel q * factor: f sits at f / factor in AO pixels.
  const vec2 at = vec2(f) / float(factor);
  const ivec2 q0 = ivec2(floor(at));
  const vec2 t = at - vec2(q0);
  const float depth = viewDepthAt(f);
  float sum = 0.0, weights = 0.0, nearestGap = 1e30, nearest = 1.0;
  for (int k = 0; k < 4; ++k) {
    const ivec2 o = ivec2(k & 1, k >> 1);
    const ivec2 q = min(q0 + o, lowSize - 1);
    const float bilinear = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
    const float gap = abs(viewDepthAt(q * factor) - depth);
    const float ao = imageLoad(source, q).r;
    if (gap < nearestGap) {
      nearestGap = gap;
      nearest = ao;
    }
    const float w = gap <= params.shape.x * depth ? bilinear : 0.0;
    sum += w * ao;
    weights += w;
  }
  imageStore(target, f, vec4(weights > 0.0 ? sum / weights : nearest));
}
