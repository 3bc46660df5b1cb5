#version 450
#extension GL_GOOGLE_include_directive : require
// The frame's last pass over its HDR colour, each pixel read once: the
// ambient occlusion taken from the ambient light (TP_AO; TP_AO_UPSAMPLE from
// half resolution, lib/ao_upsample.glsl), the haze (shared/haze.h), the
// colour stored back where it is read back, and the tonemap into the 8-bit
// image (shared/tonemap.h). One pass rather than three: on lavapipe a pass
// over the frame's RGBA32F colour costs about 10 ms at 1280x720 before it
// does anything (docs/frame-skipping.md). With AO here the water drew zero
// into the ambient image where it is seen, so AO darkens only the opaque
// surfaces. Listed (TP_LISTED_TILES), it works on the tiles
// screen_tile_list.comp listed, those whose pixels may differ from the last
// frame's, and leaves the others' 8-bit pixels as they are.
#include "shared/equirect.h"
#include "shared/frame.h"
#include "shared/haze.h"
#include "shared/resolve.h"
#include "shared/screen_tiles.h"
#include "shared/specialization.h"
#include "shared/ssao.h"
#include "shared/tonemap.h"
#include "shared/water_surface.h"

layout(constant_id = TP_SPEC_HAZE) const bool kHaze = true;
layout(constant_id = TP_SPEC_STORE_HDR) const bool kStoreHdr = true;
layout(constant_id = TP_SPEC_WRITE_LDR) const bool kWriteLdr = true;

layout(local_size_x = TP_SCREEN_TILE, local_size_y = TP_SCREEN_TILE) in;
layout(binding = 0, rgba32f) uniform image2D colorImage;
layout(binding = 1, rgba8) uniform writeonly image2D ldrImage;
layout(binding = 2) uniform Frame { FrameUniforms frame; };
layout(binding = 3) uniform sampler2D depthTexture;
layout(binding = 4) uniform sampler2D skyTexture;
layout(binding = 5) uniform Medium { CameraMedium medium; };
layout(push_constant) uniform Push { ResolveParams params; };
#ifdef TP_LISTED_TILES
layout(binding = 9) readonly buffer TileList { uint tileList[]; };  // screen_tile_list.comp's
#endif
#ifdef TP_AO
layout(binding = 6, rgba16f) uniform readonly image2D ambientImage;
#ifdef TP_AO_UPSAMPLE
layout(binding = 7, r32f) uniform readonly image2D lowAo;
layout(binding = 8, r32f) uniform readonly image2D lowViewDepth;
#include "lib/ao_upsample.glsl"
float aoAt(ivec2 p) { return upsampledAo(p); }
#else
layout(binding = 7, r32f) uniform readonly image2D aoImage;
float aoAt(ivec2 p) { return imageLoad(aoImage, p).r; }
#endif
#endif

// Aerial perspective: each pixel's surface, at the distance its depth gives,
// fades towards the sky at the horizon below it. Where no surface was drawn
// below the horizon the view runs to infinity: all haze. The sky above the
// horizon is left as it is. With the camera in the water there is no air
// between: nothing changes.
vec3 hazedAt(ivec2 p, vec3 color) {
  if (medium.extinction.w > 0.0) return color;
  const float z = texelFetch(depthTexture, p, 0).r;
  const vec2 ndc = (vec2(p) + 0.5) / vec2(params.size.xy) * 2.0 - 1.0;
  const vec4 point = frame.inverseViewProjection * vec4(ndc, z, 1.0);
  const vec3 world = point.xyz / point.w, camera = frame.cameraPosition.xyz;
  const vec3 dir = normalize(world - camera);
  const bool surface = z < 1.0;
  if (!surface && dir.y >= 0.0) return color;  // the sky
  const vec3 horizon = textureLod(skyTexture, directionToEquirect(hazeHorizonDirection(dir)), 0.0).rgb;
  return surface ? hazed(color, horizon, distance(world, camera), params.look.x) : horizon;
}

ivec2 pixel() {
#ifndef TP_LISTED_TILES
  return ivec2(gl_GlobalInvocationID.xy);
#else
  const uint tile = tileList[TP_SCREEN_TILE_LIST_HEADER + gl_WorkGroupID.x];
  const uint perRow = (params.size.x + TP_SCREEN_TILE - 1u) / TP_SCREEN_TILE;
  return ivec2(screenTileAt(tile, perRow) * uint(TP_SCREEN_TILE) + gl_LocalInvocationID.xy);
#endif
}

void main() {
  const ivec2 p = pixel();
  if (any(greaterThanEqual(p, ivec2(params.size.xy)))) return;
  vec4 color = imageLoad(colorImage, p);
#ifdef TP_AO
  color.rgb = withAo(color.rgb, imageLoad(ambientImage, p).rgb, aoAt(p));
#endif
  if (kHaze) color.rgb = hazedAt(p, color.rgb);
  if (kStoreHdr) imageStore(colorImage, p, color);
  if (kWriteLdr) imageStore(ldrImage, p, vec4(tonemap(color.rgb, params.look.y), 1.0));
}
