// What casts the sun's shadows in a frame, part of its uniforms
// (shared/frame.h); shared/sun_shadow.h asks them.
#ifndef TP_SHARED_SHADOW_CASTERS_H
#define TP_SHARED_SHADOW_CASTERS_H
#include "shared/interop.h"
#include "shared/objects.h"

TP_BEGIN

// The casters of a frame, filled with the frame's uniforms (shading/frame_uniforms.cpp).
struct ShadowCasters {
  vec4 sun;                             // x: the sun's angular radius (radians); y: spheres, z: boxes; w: 1 with a pool
  vec4 spheres[TP_MAX_SPHERES];         // the opaque spheres: xyz centre, w radius
  vec4 boxCenter[TP_MAX_BOXES];         // xyz centre, w yaw (objects.h)
  vec4 boxHalfSize[TP_MAX_BOXES];       // xyz
  vec4 pool;                            // x: half the pool's side, y: the rim's height, z: the water level, w: its ior
};

TP_END

#endif
