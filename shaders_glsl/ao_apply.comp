#version 450
#extension GL_GOOGLE_include_directive : require
// Ambient occlusion into the frame: the surfaces' passes drew direct light plus
// ambient (the sky's irradiance) and kept the ambient part apart; what AO
// occludes of it is taken away: colour = direct + ambient x AO. The AO is the
// frame's own size, or (TP_UPSAMPLE) half of it, upsampled here as
// ao_upsample.comp does (lib/ao_upsample.glsl).
#include "shared/frame.h"
#include "shared/ssao.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform image2D colorImage;
layout(binding = 1, rgba16f) uniform readonly image2D ambientImage;
#ifdef TP_UPSAMPLE
layout(binding = 2, r32f) uniform readonly image2D lowAo;
layout(binding = 3) uniform Frame { FrameUniforms frame; };
layout(binding = 4) uniform sampler2D depthTexture;
layout(binding = 5, r32f) uniform readonly image2D lowViewDepth;
layout(push_constant) uniform Push { AoUpsampleParams params; };
#include "lib/ao_upsample.glsl"
float aoAt(ivec2 p) { return upsampledAo(p); }
#else
layout(binding = 2, r32f) uniform readonly image2D aoImage;
layout(push_constant) uniform Push { AoApplyParams params; };
float aoAt(ivec2 p) { return imageLoad(aoImage, p).r; }
#endif

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(params.size.xy)))) return;
  const vec4 color = imageLoad(colorImage, p);
  const vec3 ambient = imageLoad(ambientImage, p).rgb;
  imageStore(colorImage, p, vec4(withAo(color.rgb, ambient, aoAt(p)), color.a));
}
