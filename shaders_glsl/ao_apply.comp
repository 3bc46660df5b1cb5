#version 450
#extension GL_GOOGLE_include_directive : require
// Ambient occlusion into the frame: the surfaces' passes drew direct light plus
// ambient (the sky's irradiance) and kept the ambient part apart; what AO
// occludes of it is taken away: colour = direct + ambient x AO.
#include "shared/ssao.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform image2D colorImage;
layout(binding = 1, rgba16f) uniform readonly image2D ambientImage;
layout(binding = 2, r32f) uniform readonly image2D aoImage;
layout(push_constant) uniform Push { AoApplyParams params; };

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(params.size.xy)))) return;
  const vec4 color = imageLoad(colorImage, p);
  const vec3 ambient = imageLoad(ambientImage, p).rgb;
  imageStore(colorImage, p, vec4(color.rgb - ambient * (1.0 - imageLoad(aoImage, p).r), color.a));
}
