#version 450
#extension GL_GOOGLE_include_directive : require
// Aerial perspective over the frame's colour (shared/haze.h): each pixel's
// surface, at the distance its depth gives, fades towards the sky at the
// horizon below it. Where no surface was drawn below the horizon (the
// ground's plane ended, or nothing was there) the view runs to infinity:
// all haze. The sky above the horizon is left as it is. With the camera in
// the water there is no air between: nothing changes.
#include "shared/equirect.h"
#include "shared/frame.h"
#include "shared/haze.h"
#include "shared/water_surface.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform image2D colorImage;
layout(binding = 1) uniform sampler2D depth;
layout(binding = 2) uniform sampler2D skyTexture;
layout(binding = 3) uniform Frame { FrameUniforms frame; };
layout(binding = 4) uniform Medium { CameraMedium medium; };
layout(push_constant) uniform Push { HazeParams params; };

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= params.size.x || p.y >= params.size.y || medium.extinction.w > 0.0) return;
  const float z = texelFetch(depth, ivec2(p), 0).r;
  const vec2 ndc = (vec2(p) + 0.5) / vec2(params.size.xy) * 2.0 - 1.0;
  const vec4 point = frame.inverseViewProjection * vec4(ndc, z, 1.0);
  const vec3 world = point.xyz / point.w, camera = frame.cameraPosition.xyz;
  const vec3 dir = normalize(world - camera);
  const bool surface = z < 1.0;
  if (!surface && dir.y >= 0.0) return;  // the sky
  const vec3 horizon = textureLod(skyTexture, directionToEquirect(hazeHorizonDirection(dir)), 0.0).rgb;
  vec4 color = imageLoad(colorImage, ivec2(p));
  color.rgb = surface ? hazed(color.rgb, horizon, distance(world, camera), params.haze.x) : horizon;
  imageStore(colorImage, ivec2(p), color);
}
