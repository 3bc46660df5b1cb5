#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface seen from above, deferred: its front faces store what
// shading them needs (lib/water_gbuffer.glsl) and tag the shading tiles they
// cover; water_surface_deferred.comp then shades each covered pixel once.
// On lavapipe a fragment shader runs for every 4x4 block each triangle
// touches, so the mesh's small triangles shaded forward cost several times
// the pixels they cover (docs/viewer.md#frames-per-second).
#include "shared/frame.h"
#include "shared/water_surface.h"

// The depth test before the shader, as for a shader without the tiles'
// store: lavapipe then leaves out the blocks the pool's rim and the objects
// hide, and only the tiles with a fragment seen are tagged.
layout(early_fragment_tests) in;
layout(binding = 0) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { WaterSurfaceParams surface; };
layout(binding = 9) writeonly buffer TileTags { uint tileTags[]; };
#include "lib/water_gbuffer.glsl"
#include "shared/screen_tiles.h"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 target0;
layout(location = 1) out vec4 target1;
layout(location = 2) out vec4 target2;
layout(location = 3) out vec4 target3;
layout(location = 4) out vec4 target4;

void main() {
  // As water_surface.frag takes them, for the same derivatives.
  const ViewFromAbove v = viewFromAbove(surface, frame.cameraPosition.xyz, worldPosition, worldNormal);
  const RayDifferential rd = rayDifferential(worldPosition, normalize(v.refracted));
  const WaterGbufferTexels g = packWaterSample(WaterSample(worldPosition, worldNormal, rd), float(surface.grid.z));
  target0 = g.t[0];
  target1 = g.t[1];
  target2 = g.t[2];
  target3 = g.t[3];
  target4 = g.t[4];
  const uvec2 tile = uvec2(gl_FragCoord.xy) / uint(TP_SCREEN_TILE);
  tileTags[tile.y * surface.grid.w + tile.x] = surface.grid.z;
}
