#version 450
#extension GL_GOOGLE_include_directive : require
// Linear HDR to an 8-bit sRGB preview (the curve is in shared/tonemap.h).
#include "shared/tonemap.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform readonly image2D hdrImage;
layout(binding = 1, rgba8) uniform writeonly image2D ldrImage;
layout(push_constant) uniform Push { TonemapParams params; };

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= params.size.x || p.y >= params.size.y) return;
  imageStore(ldrImage, ivec2(p), vec4(tonemap(imageLoad(hdrImage, ivec2(p)).rgb, params.exposure), 1.0));
}
