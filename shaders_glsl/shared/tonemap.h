// Push constants of the tonemap pass (HDR linear to 8-bit sRGB preview).
#ifndef TP_SHARED_TONEMAP_H
#define TP_SHARED_TONEMAP_H
#include "shared/interop.h"

TP_BEGIN

struct TonemapParams {
  uvec2 size;      // image width, height
  float exposure;  // linear scale applied before the curve
  float pad;
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::TonemapParams) == 16);
#endif

#endif
