#version 450
#extension GL_GOOGLE_include_directive : require
// One direction of the separable AO blur: a box filter, or a depth-aware
// (bilateral) one that averages only neighbours at about the pixel's own view
// depth, so that AO does not bleed across silhouettes.
#include "shared/frame.h"
#include "shared/ssao.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1, r32f) uniform readonly image2D viewDepthImage;  // the SSAO pass's aoViewDepth
layout(binding = 2, r32f) uniform readonly image2D source;
layout(binding = 3, r32f) uniform writeonly image2D target;
layout(push_constant) uniform Push { AoBlurParams params; };

// Distance in front of the camera of AO pixel q's surface.
float viewDepth(ivec2 q) { return abs(imageLoad(viewDepthImage, q).r); }

bool hasSurface(ivec2 q) { return imageLoad(viewDepthImage, q).r > 0.0; }

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 size = ivec2(params.size.xy);
  if (any(greaterThanEqual(p, size))) return;
  if (!hasSurface(p)) {
    imageStore(target, p, vec4(1.0));
    return;
  }
  const ivec2 step = params.config.x == 0u ? ivec2(1, 0) : ivec2(0, 1);
  const float depth = viewDepth(p);
  float sum = 0.0, weights = 0.0;
  for (int k = 0; k < int(params.config.y); ++k) {
    const ivec2 q = clamp(p + (params.window.x + k) * step, ivec2(0), size - 1);
    float w = 1.0;
    if (params.config.z != 0u) w = hasSurface(q) && abs(viewDepth(q) - depth) <= params.shape.x * depth ? 1.0 : 0.0;
    sum += w * imageLoad(source, q).r;
    weights += w;
  }
  // A window where no neighbour qualifies (an isolated pixel under an odd tap
  // count that leaves the pixel itself out) keeps the pixel's own value.
  imageStore(target, p, vec4(weights > 0.0 ? sum / weights : imageLoad(source, p).r));
}
