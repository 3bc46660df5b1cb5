// Push constants of the water surface pass: where the simulated grid sits in
// the world and how the water transmits light.
#ifndef TP_SHARED_WATER_SURFACE_H
#define TP_SHARED_WATER_SURFACE_H
#include "shared/interop.h"

TP_BEGIN

struct WaterSurfaceParams {
  vec4 placement;   // x, z: world position of the grid's corner (cell x = 0, z = 0); y: rest level; w: h
  vec4 absorption;  // rgb: absorption coefficient of the water in 1/m; w: index of refraction
  uvec4 grid;       // x: cells per side; yzw unused
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::WaterSurfaceParams) == 48);
#endif

#endif
