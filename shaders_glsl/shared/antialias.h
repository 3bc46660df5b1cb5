// The morphological anti-aliasing pass's push constants and the luma it finds
// edges by (antialias.comp; render/morphological_aa.cpp fills the params).
#ifndef TP_SHARED_ANTIALIAS_H
#define TP_SHARED_ANTIALIAS_H
#include "shared/interop.h"

TP_BEGIN

struct MorphologicalParams {
  uvec2 size;               // image width, height
  float contrastThreshold;  // a pixel whose neighbourhood's luma range is below this is left alone
  float relativeThreshold;  // ... or below this share of the neighbourhood's brightest luma
  float spanMax;            // the longest blend along an edge, in pixels each way
  float reduceShare;        // the share of the mean corner luma that damps the direction's normalisation
  float reduceMin;          // its least value: keeps a faint edge's direction finite
  // A pixel is on a silhouette when, along x or y, the depth buffer's second
  // difference is over this share of its two first differences: the depth of
  // a plane is affine across the screen, so textures on one surface (already
  // filtered) are left alone.
  float silhouetteShare;
};

// Display (sRGB-encoded) luma, Rec. 601 weights: what the eye sees as an
// edge in the tonemapped image.
TP_INLINE float displayLuma(vec3 display) { return dot(display, vec3(0.299f, 0.587f, 0.114f)); }

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::MorphologicalParams) == 32);
#endif

#endif
