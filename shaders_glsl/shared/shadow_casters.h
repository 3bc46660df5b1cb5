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

TP_BEGIN

// The casters of a frame, filled with the frame's uniforms (shading/frame_uniforms.cpp).
struct ShadowCasters {
  vec4 sun;                             // x: the sun's angular radius (radians); y: spheres, z: boxes; w: 1 with a pool
  vec4 spheres[TP_MAX_SPHERES];         // the opaque spheres: xyz centre, w radius
  vec4 boxCenter[TP_MAX_BOXES];         // xyz centre, w yaw (objects.h)
  vec4 boxHalfSize[TP_MAX_BOXES];       // xyz
  vec4 pool;                            // x: half the pool's side, y: the rim's height, z: the water level, w: its ior
  vec4 glassSpheres[TP_MAX_SPHERES];    // the glass spheres in the air: xyz centre, w radius; sphere i reads table i
  vec4 glass;                           // x: glass spheres
};

#ifdef __cplusplus
// The glass spheres' tables as the storage buffer holds them: sphere i's row
// r, column c at (i * TP_GLASS_TABLE_ROWS + r) * TP_GLASS_TABLE_COLUMNS + c.
struct GlassTables {
  float values[TP_MAX_SPHERES * TP_GLASS_TABLE_SIZE];
};
#endif

TP_END

#endif
