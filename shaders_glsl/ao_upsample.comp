#version 450
#extension GL_GOOGLE_include_directive : require
// Half-resolution AO to the frame (lib/ao_upsample.glsl), into an image:
// for the AO readback. Frames that only show the AO upsample it as they
// apply it (ao_apply.comp's TP_UPSAMPLE variant).
#include "shared/frame.h"
#include "shared/ssao.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D depthTexture;
layout(binding = 2, r32f) uniform readonly image2D lowAo;
layout(binding = 3, r32f) uniform writeonly image2D target;
layout(binding = 4, r32f) uniform readonly image2D lowViewDepth;
layout(push_constant) uniform Push { AoUpsampleParams params; };
#include "lib/ao_upsample.glsl"

void main() {
  const ivec2 f = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(f, ivec2(params.size.xy)))) return;
  imageStore(target, f, vec4(upsampledAo(f)));
}
