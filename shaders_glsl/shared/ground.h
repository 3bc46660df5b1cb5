// A patterned plane: the ground around the pool (the ground pass's push
// constants) and, with the same struct, the pool's tiled floor and walls.
#ifndef TP_SHARED_GROUND_H
#define TP_SHARED_GROUND_H
#include "shared/interop.h"

TP_BEGIN

struct GroundParams {
  vec4 plane;    // x: half extent, y: height, z: checker square size, w: the pool's half size (0: no pool)
  vec4 albedoA;  // rgb: the checker's even squares, or one end of the tiles' tones; w: 0 checker, 1 tiles
  vec4 albedoB;  // rgb: the odd squares, or the other end; w: each row's shift in tiles (0 stacked, 0.5 running bond)
  vec4 tiles;    // xy: 1 / (tile width along x, depth along z) in metres; zw: half the joint in tile widths, depths
  vec4 jointAlbedo;   // rgb: the grout's; w: the coping's width in metres (0: none)
  vec4 copingAlbedo;  // rgb; w: the terrace's half extent in metres (0: the tiles run to the plane's edge)
  vec4 lawnAlbedo;    // rgb: the ground past the terrace; w: half the coping's joints, in metres
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::GroundParams) == 112);
#endif

#endif
