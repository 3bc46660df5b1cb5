// What casts the sun's shadows in a frame, part of its uniforms
// (shared/frame.h); shared/sun_shadow.h asks them.
#ifndef TP_SHARED_SHADOW_CASTERS_H
#define TP_SHARED_SHADOW_CASTERS_H
#include "shared/interop.h"
#include "shared/objects.h"

// A glass sphere's sun table (shading/glass_caustic.hpp): the sun's
// irradiance behind it, relative to the open sun, on planes facing the sun,
// in the sphere's radii. Rows go along the light from the centre's plane to
// TP_GLASS_TABLE_DEPTH past it; columns go across it from the axis to
// TP_GLASS_TABLE_REACH. One table per glass sphere that casts, in a storage
// buffer at TP_GLASS_TABLES_BINDING in every pass that lights a surface.
#define TP_GLASS_TABLE_COLUMNS 64
#define TP_GLASS_TABLE_ROWS 64
#define TP_GLASS_TABLE_REACH 2.0
#define TP_GLASS_TABLE_DEPTH 16.0
#define TP_GLASS_TABLE_SIZE (TP_GLASS_TABLE_ROWS * TP_GLASS_TABLE_COLUMNS)
#define TP_GLASS_TABLES_BINDING 20
// A glass box's light grid (shading/glass_box_light.hpp): the sun's light
// under and behind it, relative to the open sun's, traced through the box
// (and the water) once per sun. Its layers are horizontal, TP_GLASS_BOX_LAYERS
// from the lowest surface that may receive it up to the box's top; across
// them, TP_GLASS_BOX_SIDE x TP_GLASS_BOX_SIDE points in coordinates sheared
// along the sun's ray (sunSheared, shared/sun_shadow.h), so that the light
// the box lets straight through stands in columns. The grids follow the
// spheres' tables in the same buffer.
#define TP_GLASS_BOX_SIDE 128
#define TP_GLASS_BOX_LAYERS 24
#define TP_GLASS_BOX_SIZE (TP_GLASS_BOX_SIDE * TP_GLASS_BOX_SIDE * TP_GLASS_BOX_LAYERS)
#define TP_GLASS_BOX_GRIDS_START (TP_MAX_SPHERES * TP_GLASS_TABLE_SIZE)

TP_BEGIN

// The casters of a frame, filled with the frame's uniforms (shading/frame_uniforms.cpp).
struct ShadowCasters {
  vec4 sun;                             // x: the sun's angular radius (radians); y: spheres, z: boxes; w: 1 with a pool
  vec4 spheres[TP_MAX_SPHERES];         // the opaque spheres: xyz centre, w radius
  vec4 boxCenter[TP_MAX_BOXES];         // xyz centre, w yaw (objects.h)
  vec4 boxHalfSize[TP_MAX_BOXES];       // xyz
  vec4 pool;                            // x: half the pool's side, y: the rim's height, z: the water level, w: its ior
  vec4 glassSpheres[TP_MAX_SPHERES];    // the glass spheres in the air: xyz centre, w radius; sphere i reads table i
  vec4 glass;                           // x: glass spheres, y: glass boxes' light grids
  // Glass box grid i: [2i] its sheared square (a0, b0, a1, b1), [2i + 1]
  // its lowest and highest layers' heights and the height the shear is taken to.
  vec4 glassBoxGrids[2 * TP_MAX_BOXES];
};

#ifdef __cplusplus
// The glass spheres' tables as the storage buffer holds them: sphere i's row
// r, column c at (i * TP_GLASS_TABLE_ROWS + r) * TP_GLASS_TABLE_COLUMNS + c;
// then glass box i's layer l, point (u, v) at TP_GLASS_BOX_GRIDS_START +
// i * TP_GLASS_BOX_SIZE + (l * TP_GLASS_BOX_SIDE + v) * TP_GLASS_BOX_SIDE + u.
struct GlassTables {
  float values[TP_GLASS_BOX_GRIDS_START + TP_MAX_BOXES * TP_GLASS_BOX_SIZE];
};
#endif

TP_END

#endif
