// The frame's last pass over its HDR colour (resolve.comp): its push
// constants, declared once for C++ and GLSL, and what its specialization
// constants say (shared/specialization.h).
#ifndef TP_SHARED_RESOLVE_H
#define TP_SHARED_RESOLVE_H
#include "shared/interop.h"

TP_BEGIN

// size and shape are laid out as AoUpsampleParams (shared/ssao.h), which
// lib/ao_upsample.glsl reads.
struct ResolveParams {
  uvec4 size;  // xy: the frame's size; zw: the AO image's size (with AO)
  vec4 shape;  // x: the AO upsample's depth tolerance, relative to the view depth; y: the AO factor
  vec4 look;   // x: the haze distance in metres (with haze); y: the exposure
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::ResolveParams) == 48);
#endif

#endif
