// Push constants of the water surface pass: where the simulated grid sits in
// the world and how the water transmits light.
#ifndef TP_SHARED_WATER_SURFACE_H
#define TP_SHARED_WATER_SURFACE_H
#include "shared/interop.h"

TP_BEGIN

struct WaterSurfaceParams {
  vec4 placement;   // x, z: world position of the grid's corner (cell x = 0, z = 0); y: rest level; w: h
  vec4 extinction;  // rgb: the water's absorption plus scattering coefficients, 1/m; w: index of refraction
  vec4 scattering;  // rgb: scattering coefficient in 1/m; w: its phase's anisotropy (water_scattering.h)
  uvec4 grid;  // x: cells per side; y: the pieces of the scattered sun's shadows (water_scattering.h);
               // z: the frame's tag, w: shading tiles per row (the deferred shading's: lib/water_gbuffer.glsl)
};

// The water's G-buffer holds this many RGBA32F targets (lib/water_gbuffer.glsl).
#define TP_WATER_GBUFFER_TARGETS 5

// The medium around the camera, decided on the GPU where the water lives
// (camera_medium.comp; render/water_model.cpp for the CPU reference) and read
// by the passes that draw what the camera sees directly, through no surface.
struct CameraMedium {
  vec4 extinction;  // rgb: extinction coefficient in 1/m (the water's under the surface, 0 in air); w: 1 under water
  vec4 scattering;  // rgb: scattering coefficient in 1/m (0 in air); w: its phase's anisotropy
  vec4 water;       // x: the water's rest level; y: its index of refraction; z: the scattering's shadow pieces; w unused
};

// A point of the surface seen from the camera above it: the view ray (unit,
// from the camera), the normal (unit, up) and the view refracted into the
// water (the zero vector past the critical angle). Every shader of the
// surface seen from above starts here, so the forward and the deferred
// shading work from the same bits.
struct ViewFromAbove {
  vec3 view, normal, refracted;
};

TP_INLINE ViewFromAbove viewFromAbove(WaterSurfaceParams s, vec3 camera, vec3 position, vec3 normal) {
  ViewFromAbove v;
  v.view = normalize(position - camera);
  v.normal = normalize(normal);
  v.refracted = refract(v.view, v.normal, 1.0f / s.extinction.w);
  return v;
}

// Where world xz falls on the surface mesh (vertex (i, j) at cell centre
// ((i + 1/2) h, (j + 1/2) h)): xy the first vertex (i, j) of its quad, zw the
// fraction inside it; clamped to the grid's vertices.
TP_INLINE vec4 gridQuadAt(WaterSurfaceParams s, vec2 xz) {
  float last = float(s.grid.x) - 1.0f;
  vec2 g = clamp((xz - vec2(s.placement.x, s.placement.z)) / s.placement.w - 0.5f, vec2(0.0f), vec2(last));
  vec2 i = min(floor(g), vec2(last - 1.0f));
  return vec4(i.x, i.y, g.x - i.x, g.y - i.y);
}

// The mesh's height (above the rest level) inside one quad from its corners'
// (x: u(i, j), y: u(i+1, j), z: u(i, j+1), w: u(i+1, j+1)), on the two
// triangles water_model.cpp's waterGridIndices makes (diagonal from (i+1, j)
// to (i, j+1)).
TP_INLINE float gridQuadHeight(vec4 corners, vec2 f) {
  if (f.x + f.y <= 1.0f) return corners.x + f.x * (corners.y - corners.x) + f.y * (corners.z - corners.x);
  return corners.w + (1.0f - f.x) * (corners.z - corners.w) + (1.0f - f.y) * (corners.y - corners.w);
}

// Whether a point's xz lies inside the water's square (edges excluded);
// only there can it be under the surface.
TP_INLINE bool overWaterSquare(WaterSurfaceParams s, vec2 xz) {
  float size = float(s.grid.x) * s.placement.w;
  vec2 local = vec2(xz.x - s.placement.x, xz.y - s.placement.z);
  return local.x > 0.0f && local.y > 0.0f && local.x < size && local.y < size;
}

// Whether point p is in the water: over the water's square and below the mesh
// (corners and fraction from gridQuadAt at p.xz).
TP_INLINE bool underWaterSurface(WaterSurfaceParams s, vec3 p, vec4 corners, vec2 f) {
  return overWaterSquare(s, vec2(p.x, p.z)) && p.y < s.placement.y + gridQuadHeight(corners, f);
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::WaterSurfaceParams) == 64);
static_assert(sizeof(tp::shader::CameraMedium) == 48);
#endif

#endif
