#version 450
#extension GL_GOOGLE_include_directive : require
// A glossy sphere's probe: the radiance reaching its centre from every
// direction of an equirectangular image, the scene without its objects
// (lib/scene_rays.glsl's backdrop: the ground, the walls, the water, the
// pool through it, the sky), which glossy_prefilter.comp then convolves
// with the lobe as it does the sky. One dispatch per glossy sphere. Each
// texel's ray carries the texel's angular size as its differential, so the
// patterns it meets are filtered over what the texel covers.
#define TP_NO_DERIVATIVES
#define TP_BACKDROP
#include "lib/scene_rays.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 2, rgba16f) uniform writeonly image2D probe;
layout(push_constant) uniform Push { GlossyProbeParams params; };

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(probe);
  if (any(greaterThanEqual(texel, size))) return;
  const vec2 uv = (vec2(texel) + 0.5) / vec2(size), step = 1.0 / vec2(size);
  const vec3 r = equirectToDirection(uv);
  const RayDifferential rd = RayDifferential(vec3(0.0), vec3(0.0), equirectToDirection(uv + vec2(step.x, 0.0)) - r,
                                             equirectToDirection(uv + vec2(0.0, step.y)) - r);
  imageStore(probe, texel, vec4(backdrop(params.center.xyz, r, rd), 1.0));
}
