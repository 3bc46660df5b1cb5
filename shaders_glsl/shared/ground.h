// Push constants of the ground pass: a finite checkered plane y = height.
#ifndef TP_SHARED_GROUND_H
#define TP_SHARED_GROUND_H
#include "shared/interop.h"

TP_BEGIN

struct GroundParams {
  vec4 plane;    // x: half extent, y: height, z: checker square size, w unused
  vec4 albedoA;  // rgb albedo of the even squares
  vec4 albedoB;  // rgb albedo of the odd squares
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::GroundParams) == 48);
#endif

#endif
