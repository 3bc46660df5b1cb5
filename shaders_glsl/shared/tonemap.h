// The tonemap's curve (HDR linear to an 8-bit sRGB preview), shared with
// C++ to tonemap CPU images (the reference) and to measure error on the
// image a viewer sees.
#ifndef TP_SHARED_TONEMAP_H
#define TP_SHARED_TONEMAP_H
#include "shared/interop.h"

TP_BEGIN

// The ACES filmic fit of Narkowicz (2015).
TP_INLINE vec3 acesFilmic(vec3 x) {
  const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

TP_INLINE vec3 srgbEncode(vec3 linear) {
  vec3 low = linear * 12.92f;
  vec3 high = 1.055f * pow(linear, vec3(1.0f / 2.4f)) - 0.055f;
  return mix(high, low, lessThanEqual(linear, vec3(0.0031308f)));
}

// Linear radiance to display sRGB in [0, 1]: exposure, the filmic curve, the transfer function.
TP_INLINE vec3 tonemap(vec3 hdr, float exposure) { return srgbEncode(acesFilmic(hdr * exposure)); }

TP_END

#endif
