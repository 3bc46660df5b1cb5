#version 450
#extension GL_GOOGLE_include_directive : require
// Linear HDR to an 8-bit sRGB preview: exposure, the ACES filmic fit of
// Narkowicz (2015), then the sRGB transfer function.
#include "shared/tonemap.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform readonly image2D hdrImage;
layout(binding = 1, rgba8) uniform writeonly image2D ldrImage;
layout(push_constant) uniform Push { TonemapParams params; };

vec3 acesFilmic(vec3 x) {
  const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 srgbEncode(vec3 linear) {
  vec3 low = linear * 12.92;
  vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
  return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= params.size.x || p.y >= params.size.y) return;
  vec3 hdr = imageLoad(hdrImage, ivec2(p)).rgb * params.exposure;
  imageStore(ldrImage, ivec2(p), vec4(srgbEncode(acesFilmic(hdr)), 1.0));
}
