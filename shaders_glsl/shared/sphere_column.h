// The volume of a sphere below the water's rest level within one column of
// the water grid (a cell's square, all heights): what the sphere displaces
// there. Integrated over the whole square, so that it changes smoothly as the
// sphere moves (a cell-centre sample jumps as the rim crosses the centre).
// Exact along x (the chord has a closed-form integral), 8-point Gauss-Legendre
// along z between the rows where the integrand has kinks;
// tests/sphere_column_test.cpp measures the error.
#ifndef TP_SHARED_SPHERE_COLUMN_H
#define TP_SHARED_SPHERE_COLUMN_H
#include "shared/interop.h"

TP_BEGIN

// Area under the half circle y = sqrt(a^2 - x^2) between x0 and x1 (clipped to [-a, a]).
TP_INLINE float halfDiscArea(float x0, float x1, float a) {
  const float lo = max(x0, -a), hi = min(x1, a);
  if (hi <= lo) return 0.0f;
  const float a2 = a * a;
  const float atHi = hi * sqrt(max(a2 - hi * hi, 0.0f)) + a2 * asin(clamp(hi / a, -1.0f, 1.0f));
  const float atLo = lo * sqrt(max(a2 - lo * lo, 0.0f)) + a2 * asin(clamp(lo / a, -1.0f, 1.0f));
  return 0.5f * (atHi - atLo);
}

// Area of the half circle of radius a above height e >= 0, between x0 and x1:
// the integral of max(sqrt(a^2 - x^2) - e, 0).
TP_INLINE float discSegmentArea(float x0, float x1, float a, float e) {
  if (a <= e) return 0.0f;
  const float w = sqrt(a * a - e * e);  // where the circle crosses height e
  const float lo = max(x0, -w), hi = min(x1, w);
  if (hi <= lo) return 0.0f;
  return halfDiscArea(lo, hi, a) - e * (hi - lo);
}

// Integral over x in [x0, x1] of the length of the sphere's vertical chord
// below the level, along the line at z: coordinates relative to the sphere's
// centre, `above` the level's height over the centre. The chord is
// s + min(s, above) with s = sqrt(a^2 - x^2), a^2 = r^2 - z^2 (cut at 0).
TP_INLINE float chordIntegral(float x0, float x1, float z, float radius, float above) {
  const float a2 = radius * radius - z * z;
  if (a2 <= 0.0f) return 0.0f;
  const float a = sqrt(a2);
  if (above >= 0.0f) return 2.0f * halfDiscArea(x0, x1, a) - discSegmentArea(x0, x1, a, above);
  return discSegmentArea(x0, x1, a, -above);
}

// The row z = sqrt(r^2 - rho^2) where the chord's circle, of radius a(z) =
// rho, meets a cut (-1 when it never does: rho >= r).
TP_INLINE float kinkRow(float rho, float radius) { return rho < radius ? sqrt(radius * radius - rho * rho) : -1.0f; }

// The first of the rows -z and z above `from`, if below `to` (else `to`).
TP_INLINE float nextKink(float from, float to, float z) {
  if (z < 0.0f) return to;
  if (-z > from && -z < to) return -z;
  if (z > from && z < to) return z;
  return to;
}

// 8-point Gauss-Legendre over z in [z0, z1] of chordIntegral(x0, x1, z).
TP_INLINE float gaussOverRows(float x0, float x1, float z0, float z1, float radius, float above) {
  const float mid = 0.5f * (z0 + z1), halfWidth = 0.5f * (z1 - z0);
  // Nodes and weights on [-1, 1], in symmetric pairs.
  const float node0 = 0.1834346424956498f, weight0 = 0.3626837833783620f;
  const float node1 = 0.5255324099163290f, weight1 = 0.3137066458778873f;
  const float node2 = 0.7966664774136267f, weight2 = 0.2223810344533745f;
  const float node3 = 0.9602898564975363f, weight3 = 0.1012285362903763f;
  float sum = 0.0f;
  sum += weight0 * (chordIntegral(x0, x1, mid - halfWidth * node0, radius, above) +
                    chordIntegral(x0, x1, mid + halfWidth * node0, radius, above));
  sum += weight1 * (chordIntegral(x0, x1, mid - halfWidth * node1, radius, above) +
                    chordIntegral(x0, x1, mid + halfWidth * node1, radius, above));
  sum += weight2 * (chordIntegral(x0, x1, mid - halfWidth * node2, radius, above) +
                    chordIntegral(x0, x1, mid + halfWidth * node2, radius, above));
  sum += weight3 * (chordIntegral(x0, x1, mid - halfWidth * node3, radius, above) +
                    chordIntegral(x0, x1, mid + halfWidth * node3, radius, above));
  return halfWidth * sum;
}

// Volume of the sphere (centre, radius) below `level` within the column over
// the square [lo, hi] (x and z, the same frame as the centre's x and z).
// chordIntegral is smooth in z but where the circle a(z) meets the square's
// x edges, the level's circle, or the level's circle meets the x edges: the
// rows are split there and each piece takes 8-point Gauss-Legendre.
TP_INLINE float sphereColumnVolume(vec2 lo, vec2 hi, vec3 center, float radius, float level) {
  const float x0 = lo.x - center.x, x1 = hi.x - center.x;
  const float z0 = max(lo.y - center.z, -radius), z1 = min(hi.y - center.z, radius);
  if (z1 <= z0 || x1 <= -radius || x0 >= radius) return 0.0f;
  const float above = level - center.y;
  const float e2 = above * above;
  const float kink0 = kinkRow(abs(x0), radius), kink1 = kinkRow(abs(x1), radius);
  const float kink2 = kinkRow(abs(above), radius);
  const float kink3 = kinkRow(sqrt(x0 * x0 + e2), radius), kink4 = kinkRow(sqrt(x1 * x1 + e2), radius);
  float sum = 0.0f;
  float from = z0;
  for (int piece = 0; piece < 12 && from < z1; ++piece) {  // at most 10 kinks: 11 pieces
    float to = z1;
    to = nextKink(from, to, kink0);
    to = nextKink(from, to, kink1);
    to = nextKink(from, to, kink2);
    to = nextKink(from, to, kink3);
    to = nextKink(from, to, kink4);
    sum += gaussOverRows(x0, x1, from, to, radius, above);
    from = to;
  }
  return sum;
}

TP_END

#endif
