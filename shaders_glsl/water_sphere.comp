#version 450
#extension GL_GOOGLE_include_directive : require
// A sphere moving through the water displaces it by volume, column by column:
// the surface rises by the sphere's volume below the rest level within the
// column's square at the new position, minus that at the old one
// (shared/sphere_column.h), over the square's area. With kSpread (the
// scene's water.sphere_forcing) the volume is spread over the surface as the
// flow around a body lifts it (shared/sphere_spread.h), both positions with
// the bump of this step's speed. The wave equation
// acts on the surface, so the water itself (heights minus the sphere's
// submerged volume) is conserved to round-off. Docs: docs/water-numerics.md.
// Marks the tiles it changes so that an active-tile step computes them.
#include "shared/sphere_column.h"
#include "shared/sphere_spread.h"
#include "shared/water.h"

layout(local_size_x = TP_WATER_TILE, local_size_y = TP_WATER_TILE) in;
layout(binding = 0) buffer State { vec4 cells[]; };
layout(binding = 1) buffer ChangedAt { uint changedAt[]; };
layout(push_constant) uniform Push { WaterSphereParams params; };
layout(constant_id = 0) const bool kSpread = false;

#include "lib/water_tile_mark.glsl"

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  bool changed = false;
  if (p.x < params.n && p.y < params.n) {
    const vec2 lo = vec2(p) * params.h, hi = vec2(p + 1u) * params.h;
    const float radius = params.oldCenter.w, level = params.newCenter.w;
    const float length = float(params.n) * params.h;
    const bool wrap = params.wrap != 0u;
    const float before =
        kSpread ? sphereSpreadVolume(lo, hi, params.oldCenter.xyz, radius, level, length, params.spreadDepth, wrap,
                                     params.widening, params.fast, params.topShare)
                : sphereColumnVolume(lo, hi, params.oldCenter.xyz, radius, level);
    const float after =
        kSpread ? sphereSpreadVolume(lo, hi, params.newCenter.xyz, radius, level, length, params.spreadDepth, wrap,
                                     params.widening, params.fast, params.topShare)
                : sphereColumnVolume(lo, hi, params.newCenter.xyz, radius, level);
    if (before != after) {
      const uint index = p.y * params.n + p.x;
      const vec4 old = cells[index];
      vec4 moved = old;
      moved.y += (after - before) / (params.h * params.h);
      cells[index] = moved;
      changed = cellChanged(old, moved);
    }
  }
  markTileIfChanged(changed, gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x, params.markStep);
}
