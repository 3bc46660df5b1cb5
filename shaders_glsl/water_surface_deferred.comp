#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface seen from above, accurate refraction, shaded once per
// pixel: one workgroup for each tile screen_tile_list.comp listed, each
// pixel the G-buffer pass drew this frame shaded from what it stored
// (lib/water_gbuffer.glsl) as water_surface.frag shades it, into the frame.
#define TP_NO_DERIVATIVES
#include "lib/water_light.glsl"
#include "lib/water_gbuffer.glsl"
#include "shared/screen_tiles.h"

layout(local_size_x = TP_SCREEN_TILE, local_size_y = TP_SCREEN_TILE) in;
layout(binding = 9, rgba32f) uniform writeonly image2D colorImage;
// The G-buffer's targets, in lib/water_gbuffer.glsl's order.
layout(binding = 10, rgba32f) uniform readonly image2D gbuffer0;
layout(binding = 11, rgba32f) uniform readonly image2D gbuffer1;
layout(binding = 12, rgba32f) uniform readonly image2D gbuffer2;
layout(binding = 13, rgba32f) uniform readonly image2D gbuffer3;
layout(binding = 14, rgba32f) uniform readonly image2D gbuffer4;
layout(binding = 15) readonly buffer TileList { uint tileList[]; };  // screen_tile_list.comp's
#ifdef TP_CLEAR_AMBIENT
// The opaque surfaces' ambient part, which the resolve pass takes AO from:
// none where the water is seen.
layout(binding = 16, rgba16f) uniform writeonly image2D ambientImage;
#endif

void main() {
  const uint tile = tileList[TP_SCREEN_TILE_LIST_HEADER + gl_WorkGroupID.x];
  const ivec2 p = ivec2(screenTileAt(tile, surface.grid.w) * uint(TP_SCREEN_TILE) + gl_LocalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(colorImage)))) return;
  WaterGbufferTexels g;
  g.t[0] = imageLoad(gbuffer0, p);
  if (g.t[0].w != float(surface.grid.z)) return;  // not drawn this frame
  g.t[1] = imageLoad(gbuffer1, p);
  g.t[2] = imageLoad(gbuffer2, p);
  g.t[3] = imageLoad(gbuffer3, p);
  g.t[4] = imageLoad(gbuffer4, p);
  const WaterSample s = unpackWaterSample(g);
  const ViewFromAbove v = viewFromAbove(surface, frame.cameraPosition.xyz, s.position, s.normal);
  imageStore(colorImage, p, vec4(seenFromAbove(s.position, v, s.rd), 1.0));
#ifdef TP_CLEAR_AMBIENT
  imageStore(ambientImage, p, vec4(0.0));
#endif
}
