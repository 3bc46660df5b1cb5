// The sky's irradiance as 9 real spherical-harmonic coefficients (bands 0-2,
// Ramamoorthi and Hanrahan 2001), compiled both as GLSL and as C++: the CPU
// projects the sky once per sky (render/sky_sh.hpp), the raster passes and
// the reference tracer evaluate the irradiance for each normal with the same
// function. Bands 0-2 hold a clamped cosine's convolution to within 1% for
// any sky, and exactly for the uniform sky above the horizon (whose band-2
// coefficients are zero and whose odd bands above 1 the cosine removes).
#ifndef TP_SHARED_SH9_H
#define TP_SHARED_SH9_H
#include "shared/equirect.h"
#include "shared/interop.h"

TP_BEGIN

// The basis with y as the polar axis (the sky's up):
// Y0 = 1/(2 sqrt(pi)); Y1..3 = sqrt(3/(4pi)) (y, z, x);
// Y4, Y5, Y7 = sqrt(15/(4pi)) (xy, yz, xz); Y6 = sqrt(5/(16pi)) (3y^2 - 1);
// Y8 = sqrt(15/(16pi)) (x^2 - z^2).
const float kSh0 = 0.28209479177387814f;
const float kSh1 = 0.48860251190291992f;
const float kSh2 = 1.09254843059207907f;
const float kSh20 = 0.31539156525252001f;
const float kSh22 = 0.54627421529603954f;

// The clamped cosine's band factors: A0 = pi, A1 = 2pi/3, A2 = pi/4.
const float kShCosine0 = 3.14159265358979323846f;
const float kShCosine1 = 2.09439510239319549f;
const float kShCosine2 = 0.78539816339744831f;

// rgb in xyz of each coefficient; w unused (std140 and std430 alike).
struct Sh9 {
  vec4 c[9];
};

TP_INLINE float sh9Basis(uint i, vec3 d) {
  if (i == 0u) return kSh0;
  if (i == 1u) return kSh1 * d.y;
  if (i == 2u) return kSh1 * d.z;
  if (i == 3u) return kSh1 * d.x;
  if (i == 4u) return kSh2 * d.x * d.y;
  if (i == 5u) return kSh2 * d.y * d.z;
  if (i == 6u) return kSh20 * (3.0f * d.y * d.y - 1.0f);
  if (i == 7u) return kSh2 * d.x * d.z;
  return kSh22 * (d.x * d.x - d.z * d.z);
}

// The band of coefficient i (0, 1 or 2).
TP_INLINE uint sh9Band(uint i) { return i == 0u ? 0u : (i < 4u ? 1u : 2u); }

// Irradiance on a surface with unit normal n: the radiance's coefficients
// convolved with the clamped cosine; clamped at 0, where the truncated series
// of a peaked sky (a sun in an image) rings below it facing away from the peak.
TP_INLINE vec3 sh9Irradiance(Sh9 sh, vec3 n) {
  vec3 e = vec3(0.0f);
  for (uint i = 0u; i < 9u; ++i) {
    uint band = sh9Band(i);
    float a = band == 0u ? kShCosine0 : (band == 1u ? kShCosine1 : kShCosine2);
    e += a * sh9Basis(i, n) * vec3(sh.c[i]);
  }
  return max(e, vec3(0.0f));
}

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::Sh9) == 144);
#endif

#endif
