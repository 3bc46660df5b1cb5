// Half-resolution AO to the frame, depth aware (a joint bilateral upsample):
// each frame pixel blends the four AO pixels around it with bilinear weights,
// keeping only those whose surface lies at about its own view depth, so that
// AO does not leak across silhouettes; where none does, the nearest in depth.
// Where no surface is, 1. For ao_upsample.comp and for ao_apply.comp's
// variant that upsamples as it applies (one pass less over the frame); the
// includer declares `frame`, `depthTexture` (the frame's), `lowAo`,
// `lowViewDepth` (the SSAO pass's aoViewDepth) and `params`
// (AoUpsampleParams). The AO pixels' depths are those the SSAO pass saw, so
// the upsample may run after the water has drawn over the depth buffer.
#ifndef TP_LIB_AO_UPSAMPLE
#define TP_LIB_AO_UPSAMPLE
#include "shared/ssao.h"

float viewDepthAt(ivec2 framePixel) {
  return -viewPositionFromDepth(frame.inverseProjection, vec2(0.5), texelFetch(depthTexture, framePixel, 0).r).z;
}

float upsampledAo(ivec2 f) {
  if (texelFetch(depthTexture, f, 0).r >= 1.0) return 1.0;
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
    const float gap = abs(abs(imageLoad(lowViewDepth, q).r) - depth);
    const float ao = imageLoad(lowAo, q).r;
    if (gap < nearestGap) {
      nearestGap = gap;
      nearest = ao;
    }
    const float w = gap <= params.shape.x * depth ? bilinear : 0.0;
    sum += w * ao;
    weights += w;
  }
  return weights > 0.0 ? sum / weights : nearest;
}

#endif
