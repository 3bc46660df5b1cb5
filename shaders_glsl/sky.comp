#version 450
#extension GL_GOOGLE_include_directive : require
// Fills the equirectangular HDR sky texture from the procedural sky.
#include "shared/sky.h"
#include "shared/shading.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D skyImage;
layout(push_constant) uniform Push { SkyParams sky; };

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  const uvec2 size = uvec2(sky.counts.x, sky.counts.x / 2u);
  if (p.x >= size.x || p.y >= size.y) return;
  vec2 uv = (vec2(p) + 0.5) / vec2(size);
  vec3 d = equirectToDirection(uv);
  imageStore(skyImage, ivec2(p), vec4(skyRadiance(sky, d, 1.0), 1.0));
}
