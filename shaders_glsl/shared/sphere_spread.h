// The water a sphere displaces, spread over the surface as the flow around
// a body lifts it: the "spread" forcing (water.sphere_forcing). The sphere's
// part below the rest level is replaced by a Gaussian bump of the same
// volume and the same horizontal second moment, widened by its mean depth
// (a body deeper down lifts a wider, lower patch of surface, as the
// potential flow of a source under a free surface does). The bump is
// integrated exactly over each cell's square and folded back at the walls,
// so the cells hold the whole submerged volume and it changes smoothly as
// the sphere moves, whatever the grid. docs/water-numerics.md derives it;
// tests/sphere_spread_test.cpp checks it against quadrature.
#ifndef TP_SHARED_SPHERE_SPREAD_H
#define TP_SHARED_SPHERE_SPREAD_H
#include "shared/constants.h"
#include "shared/interop.h"

TP_BEGIN

// The submerged part of a sphere of `radius` whose bottom is `depth` below
// the level (depth = level - centre.y + radius): its volume, its horizontal
// variance per axis about the centre's vertical, and its mean depth below
// the level. Written in the cap's height e, so that thin caps keep their
// precision.
struct SubmergedMoments {
  float volume;
  float variance;   // m^2, along x and along z alike
  float meanDepth;  // m
};

TP_INLINE SubmergedMoments submergedMoments(float radius, float depth) {
  const float r = radius, e = clamp(depth, 0.0f, 2.0f * radius);
  SubmergedMoments m;
  m.volume = kPi * e * e * (3.0f * r - e) / 3.0f;
  if (e <= 0.0f) {
    m.variance = 0.0f;
    m.meanDepth = 0.0f;
    return m;
  }
  // A slice at height s over the bottom is a disc of radius^2 2 r s - s^2.
  // Its second moment per axis, pi rho^4 / 4, and its height, integrated
  // over s in [0, e] and divided by the volume, pi e^2 (3 r - e) / 3:
  m.variance = 0.75f * e * (4.0f * r * r / 3.0f - r * e + 0.2f * e * e) / (3.0f * r - e);
  const float centroidHeight = e * (8.0f * r - 3.0f * e) / (4.0f * (3.0f * r - e));
  m.meanDepth = depth - centroidHeight;
  return m;
}

// The bump's variance: the submerged part's horizontal spread and
// depthFactor times its mean depth, added.
TP_INLINE float spreadVariance(SubmergedMoments m, float depthFactor) {
  const float widening = depthFactor * m.meanDepth;
  return m.variance + widening * widening;
}

// The same for a sphere moving faster than the waves. The water it lifts
// cannot run ahead of it and stands where the bump puts it, so the bump is
// widened until its peak, volume / (2 pi variance), stands at most topShare
// of the way up to the sphere's top (`top` over the level). `fast` in [0, 1]
// says how far past the wave speed the sphere moves (0: not at all, and the
// variance is the one above to the bit). A sphere that barely breaks the
// surface may be washed over: the widening fades as its top sinks, so that
// it vanishes, without a jump, as the top goes under.
TP_INLINE float fastSpreadVariance(SubmergedMoments m, float variance, float radius, float top, float fast,
                                   float topShare) {
  if (fast <= 0.0f || top <= 0.0f) return variance;
  const float capped = m.volume / (2.0f * kPi * topShare * top);
  return variance + fast * smoothstep(0.0f, radius, top) * max(capped - variance, 0.0f);
}

// The standard normal's upper tail P(Z > u) for u >= 0 (Abramowitz and
// Stegun 7.1.26, absolute error under 1e-7). Zero past 8: the tail there
// is under 1e-15, and a bump that ends leaves the water beyond it untouched.
TP_INLINE float normalTail(float u) {
  if (u > 8.0f) return 0.0f;
  const float x = u * 0.70710678118654752f;
  const float t = 1.0f / (1.0f + 0.3275911f * x);
  const float poly =
      t * (0.254829592f + t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
  return 0.5f * poly * exp(-x * x);
}

// The share of a normal distribution (mean c, deviation sigma > 0) in
// [x0, x1], from the tail on the side that keeps its precision. Cells that
// share an edge evaluate it alike, so the shares of a row sum to its span.
TP_INLINE float normalShare(float x0, float x1, float c, float sigma) {
  const float u0 = (x0 - c) / sigma, u1 = (x1 - c) / sigma;
  if (u0 >= 0.0f) return normalTail(u0) - normalTail(u1);
  if (u1 <= 0.0f) return normalTail(-u1) - normalTail(-u0);
  return 1.0f - normalTail(-u0) - normalTail(u1);
}

// The same over one axis of a pool of `length`, with the part beyond a wall
// folded back in: mirrored at the walls (wrap = false), or carried round to
// the other side (wrap = true). The centre and its nearest images first;
// further images only for a bump wide enough to reach the pool from them
// (one widened near the wave speed), so that a narrow bump's sum is the
// three terms alone. Every image nearer the pool than 8 sigma is added.
TP_INLINE float pooledShare(float x0, float x1, float c, float sigma, float length, bool wrap) {
  const float below = wrap ? c + length : -c, above = wrap ? c - length : 2.0f * length - c;
  float share =
      normalShare(x0, x1, c, sigma) + normalShare(x0, x1, below, sigma) + normalShare(x0, x1, above, sigma);
  // The images added at round j lie at least (j - 1) period + length from
  // the pool, less how far the centre is beyond a wall.
  const float period = wrap ? length : 2.0f * length;
  const float outside = max(max(-c, c - length), 0.0f);
  for (int j = 1; float(j - 1) * period + length - outside < 8.0f * sigma; ++j) {
    const float shift = float(j) * period;
    if (wrap) {
      share += normalShare(x0, x1, c + shift + length, sigma) + normalShare(x0, x1, c - shift - length, sigma);
    } else {
      share += normalShare(x0, x1, c + shift, sigma) + normalShare(x0, x1, c - shift, sigma) +
               normalShare(x0, x1, -c - shift, sigma) + normalShare(x0, x1, 2.0f * length - c + shift, sigma);
    }
  }
  return share;
}

// The share of a ball's volume below the plane x = t r across it, its
// centre at 0: the ball's volume along x goes as r^2 - x^2.
TP_INLINE float ballShareBelow(float t) {
  const float s = clamp(t, -1.0f, 1.0f);
  return (2.0f + 3.0f * s - s * s * s) / 4.0f;
}

// The share of the ball (centre c along one axis, radius) between the walls
// at 0 and `length`: 1 inside the pool, fading as it passes into a wall, 0
// beyond. Exact for a ball through one wall.
TP_INLINE float ballShareInside(float c, float radius, float length) {
  return ballShareBelow((length - c) / radius) - ballShareBelow(-c / radius);
}

// Volume the sphere (centre, radius) displaces into the column over the
// square [lo, hi] of a pool of `length` per side, the level at `level`:
// its submerged volume as a bump of variance moments.variance plus
// (depthFactor * meanDepth)^2, that times `widening` near the wave speed
// (sim::wakeWidening; 1 slower), and widened when `fast` as
// fastSpreadVariance says. With walls, only the share of the sphere between
// them displaces water (as with the column forcing, a sphere dragged through
// a wall leaves the pool's water as it was); the grid that wraps round has
// none.
TP_INLINE float sphereSpreadVolume(vec2 lo, vec2 hi, vec3 center, float radius, float level, float length,
                                   float depthFactor, bool wrap, float widening, float fast, float topShare) {
  const SubmergedMoments m = submergedMoments(radius, level - center.y + radius);
  if (m.volume <= 0.0f) return 0.0f;
  const float top = center.y + radius - level;
  const float sigma =
      sqrt(fastSpreadVariance(m, widening * spreadVariance(m, depthFactor), radius, top, fast, topShare));
  const float inside =
      wrap ? 1.0f : ballShareInside(center.x, radius, length) * ballShareInside(center.z, radius, length);
  return m.volume * inside * pooledShare(lo.x, hi.x, center.x, sigma, length, wrap) *
         pooledShare(lo.y, hi.y, center.z, sigma, length, wrap);
}

TP_END

#endif
