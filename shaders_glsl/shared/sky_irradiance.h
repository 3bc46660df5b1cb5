// The sky's irradiance for any normal, as one polynomial in the normal's
// coordinates, compiled both as GLSL and as C++: the CPU fits it once per
// scene (shading/sky_irradiance.cpp), the raster passes and the model tracer
// evaluate it per normal with the same function.
//
// Why a polynomial: the irradiance is the radiance round the whole sphere
// convolved with the clamped cosine, which keeps spherical-harmonic band 1
// and the even bands (its odd bands above 1 are zero). Bands 0-2 (SH9) miss
// a bright blob's light by up to 8% (a delta light 60 degrees from the
// normal); bands 0-6 by under 2%. Band 1 is a linear form of n, and bands
// 0, 2, 4 and 6 together are exactly the sextic forms of n on the unit
// sphere (28 of each), so x, y, z and the 28 monomials x^a y^b z^c with
// a + b + c = 6 hold them, and evaluating them is 31 multiply-adds.
#ifndef TP_SHARED_SKY_IRRADIANCE_H
#define TP_SHARED_SKY_IRRADIANCE_H
#include "shared/interop.h"

TP_BEGIN

const int kSkyIrradianceSextics = 28;
const int kSkyIrradianceTerms = 3 + kSkyIrradianceSextics;

// rgb in xyz of each coefficient; w unused (std140 and std430 alike).
struct SkyIrradiance {
  // Coefficient k: x, y, z for k = 0-2, then the monomials x^a y^b z^c
  // with a from 6 down to 0 and, for each, b from 6 - a down to 0.
  vec4 c[kSkyIrradianceTerms];
};

// The polynomial at unit normal n, unclamped: linear in the coefficients
// (what the CPU's fit takes the basis from).
TP_INLINE vec3 skyIrradianceSum(SkyIrradiance s, vec3 n) {
  vec3 e = vec3(s.c[0]) * n.x + vec3(s.c[1]) * n.y + vec3(s.c[2]) * n.z;
  // Written out term by term: as a loop over arrays of powers, lavapipe
  // took 363 s to compile the glass scene's shaders against 54 s so.
  float x = n.x, y = n.y, z = n.z;
  float x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x, x6 = x5 * x;
  float y2 = y * y, y3 = y2 * y, y4 = y3 * y, y5 = y4 * y, y6 = y5 * y;
  float z2 = z * z, z3 = z2 * z, z4 = z3 * z, z5 = z4 * z, z6 = z5 * z;
  e += vec3(s.c[3]) * (x6);
  e += vec3(s.c[4]) * (x5 * y);
  e += vec3(s.c[5]) * (x5 * z);
  e += vec3(s.c[6]) * (x4 * y2);
  e += vec3(s.c[7]) * (x4 * y * z);
  e += vec3(s.c[8]) * (x4 * z2);
  e += vec3(s.c[9]) * (x3 * y3);
  e += vec3(s.c[10]) * (x3 * y2 * z);
  e += vec3(s.c[11]) * (x3 * y * z2);
  e += vec3(s.c[12]) * (x3 * z3);
  e += vec3(s.c[13]) * (x2 * y4);
  e += vec3(s.c[14]) * (x2 * y3 * z);
  e += vec3(s.c[15]) * (x2 * y2 * z2);
  e += vec3(s.c[16]) * (x2 * y * z3);
  e += vec3(s.c[17]) * (x2 * z4);
  e += vec3(s.c[18]) * (x * y5);
  e += vec3(s.c[19]) * (x * y4 * z);
  e += vec3(s.c[20]) * (x * y3 * z2);
  e += vec3(s.c[21]) * (x * y2 * z3);
  e += vec3(s.c[22]) * (x * y * z4);
  e += vec3(s.c[23]) * (x * z5);
  e += vec3(s.c[24]) * (y6);
  e += vec3(s.c[25]) * (y5 * z);
  e += vec3(s.c[26]) * (y4 * z2);
  e += vec3(s.c[27]) * (y3 * z3);
  e += vec3(s.c[28]) * (y2 * z4);
  e += vec3(s.c[29]) * (y * z5);
  e += vec3(s.c[30]) * (z6);
  return e;
}

// The irradiance on a surface with unit normal n; clamped at 0, where the
// truncated series of a peaked sky rings below it facing away from the peak.
TP_INLINE vec3 skyIrradiance(SkyIrradiance s, vec3 n) { return max(skyIrradianceSum(s, n), vec3(0.0f)); }

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::SkyIrradiance) == 31 * 16);
#endif

#endif
