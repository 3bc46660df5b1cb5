#version 450
#extension GL_GOOGLE_include_directive : require
// Morphological anti-aliasing of the tonemapped frame's silhouettes, after
// the directional blend of Lottes's FXAA: on a silhouette (the depth buffer
// says where) whose display luma over the pixel's corners spans more than a
// threshold, the edge's direction is taken across the luma's gradient, and
// the pixel becomes the mean of bilinear taps along it. The wider blend is
// kept unless it leaves the neighbourhood's luma range (it crossed another
// edge); then the narrower one. Textures within a surface are filtered where
// they are drawn: blurring them again only moves them from the reference.
#include "shared/antialias.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D display;
layout(binding = 1, rgba8) uniform writeonly image2D ldrImage;
layout(binding = 2) uniform sampler2D depth;
layout(push_constant) uniform Push { MorphologicalParams params; };

vec3 tap(vec2 uv) { return textureLod(display, uv, 0.0).rgb; }

float depthAt(ivec2 p) { return texelFetch(depth, clamp(p, ivec2(0), ivec2(params.size) - 1), 0).r; }

// Whether the depth bends or jumps at p along `axis`, where one plane's is straight.
bool bendsAlong(ivec2 p, ivec2 axis) {
  const float before = depthAt(p - axis), here = depthAt(p), after = depthAt(p + axis);
  const float bend = abs(before + after - 2.0 * here);
  return bend > params.silhouetteShare * (abs(after - here) + abs(here - before));
}

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= params.size.x || p.y >= params.size.y) return;
  const vec2 texel = 1.0 / vec2(params.size);
  const vec2 uv = (vec2(p) + 0.5) * texel;
  const vec3 centre = texelFetch(display, ivec2(p), 0).rgb;
  // Most pixels are inside a surface: the depth alone says so, before any tap.
  if (!bendsAlong(ivec2(p), ivec2(1, 0)) && !bendsAlong(ivec2(p), ivec2(0, 1))) {
    imageStore(ldrImage, ivec2(p), vec4(centre, 1.0));
    return;
  }
  // The corners, each the mean of four pixels: half a texel out on both axes.
  const float nw = displayLuma(tap(uv + vec2(-0.5, -0.5) * texel));
  const float ne = displayLuma(tap(uv + vec2(0.5, -0.5) * texel));
  const float sw = displayLuma(tap(uv + vec2(-0.5, 0.5) * texel));
  const float se = displayLuma(tap(uv + vec2(0.5, 0.5) * texel));
  const float m = displayLuma(centre);
  const float lo = min(m, min(min(nw, ne), min(sw, se)));
  const float hi = max(m, max(max(nw, ne), max(sw, se)));
  if (hi - lo < max(params.contrastThreshold, params.relativeThreshold * hi)) {
    imageStore(ldrImage, ivec2(p), vec4(centre, 1.0));
    return;
  }
  // Along the edge: perpendicular to the luma's gradient over the corners.
  vec2 along = vec2((sw + se) - (nw + ne), (nw + sw) - (ne + se));
  // Scaled so its shorter component is about one pixel, the longer one the
  // edge's run; damped where the corners are dark, where noise dominates.
  const float reduce = max(0.25 * (nw + ne + sw + se) * params.reduceShare, params.reduceMin);
  along = clamp(along / (min(abs(along.x), abs(along.y)) + reduce), -params.spanMax, params.spanMax) * texel;
  // Taps at -1/6 and +1/6 of the run (narrow), and at its ends (wide).
  const vec3 narrow = 0.5 * (tap(uv - along / 6.0) + tap(uv + along / 6.0));
  const vec3 wide = 0.5 * narrow + 0.25 * (tap(uv - 0.5 * along) + tap(uv + 0.5 * along));
  const float wideLuma = displayLuma(wide);
  const vec3 result = (wideLuma < lo || wideLuma > hi) ? narrow : wide;
  imageStore(ldrImage, ivec2(p), vec4(result, 1.0));
}
