// The noise family, one text for C++ and GLSL: an integer hash, value noise
// (bilinear and cubic), gradient noise (Perlin, quintic fade) and fractal
// sums. Only integer operations, multiplies, adds and floor, each written so
// that both languages round the same way: the GPU and the CPU agree to the bit
// (tests/noise_test.cpp checks it).
#ifndef TP_SHARED_NOISE_H
#define TP_SHARED_NOISE_H
#include "shared/interop.h"

TP_BEGIN

// PCG-style integer hash (Jarzynski and Olano, 2020).
TP_INLINE uint hashUint(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

TP_INLINE uint hashCell(int x, int y, uint seed) { return hashUint(uint(x) + hashUint(uint(y) + hashUint(seed))); }

// A lattice value in [0, 1): the top 24 bits, exact in float.
TP_INLINE float latticeValue(int x, int y, uint seed) {
  return float(hashCell(x, y, seed) >> 8u) * (1.0f / 16777216.0f);
}

// Bilinear value noise in [0, 1]: continuous, with kinks at the lattice lines.
TP_INLINE float valueNoiseBilinear(vec2 p, uint seed) {
  vec2 cell = floor(p);
  int x = int(cell.x), y = int(cell.y);
  TP_PRECISE float fx = p.x - cell.x;
  TP_PRECISE float fy = p.y - cell.y;
  TP_PRECISE float a = latticeValue(x, y, seed), b = latticeValue(x + 1, y, seed);
  TP_PRECISE float c = latticeValue(x, y + 1, seed), d = latticeValue(x + 1, y + 1, seed);
  TP_PRECISE float bottom = a + (b - a) * fx;
  TP_PRECISE float top = c + (d - c) * fx;
  return bottom + (top - bottom) * fy;
}

// Value noise with the cubic fade 3t^2 - 2t^3: in [0, 1], smooth (C1).
TP_INLINE float valueNoiseCubic(vec2 p, uint seed) {
  vec2 cell = floor(p);
  int x = int(cell.x), y = int(cell.y);
  TP_PRECISE float fx = p.x - cell.x;
  TP_PRECISE float fy = p.y - cell.y;
  TP_PRECISE float sx = fx * fx * (3.0f - 2.0f * fx);
  TP_PRECISE float sy = fy * fy * (3.0f - 2.0f * fy);
  TP_PRECISE float a = latticeValue(x, y, seed), b = latticeValue(x + 1, y, seed);
  TP_PRECISE float c = latticeValue(x, y + 1, seed), d = latticeValue(x + 1, y + 1, seed);
  TP_PRECISE float bottom = a + (b - a) * sx;
  TP_PRECISE float top = c + (d - c) * sx;
  return bottom + (top - bottom) * sy;
}

// The lattice point's gradient, one of the four axes or four diagonals
// (1, 1)-style, dotted with the offset (fx, fy) from it.
TP_INLINE float gradientDot(int x, int y, uint seed, float fx, float fy) {
  uint h = hashCell(x, y, seed) & 7u;
  if (h == 0u) return fx;
  if (h == 1u) return -fx;
  if (h == 2u) return fy;
  if (h == 3u) return -fy;
  TP_PRECISE float u = (h & 1u) != 0u ? -fx : fx;
  TP_PRECISE float v = (h & 2u) != 0u ? -fy : fy;
  TP_PRECISE float diagonal = u + v;
  return diagonal;
}

TP_INLINE float quintic(float t) {
  TP_PRECISE float q = t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
  return q;
}

// Gradient (Perlin) noise with the quintic fade 6t^5 - 15t^4 + 10t^3: C2,
// zero at the lattice points, within [-1, 1].
TP_INLINE float gradientNoise(vec2 p, uint seed) {
  vec2 cell = floor(p);
  int x = int(cell.x), y = int(cell.y);
  TP_PRECISE float fx = p.x - cell.x;
  TP_PRECISE float fy = p.y - cell.y;
  TP_PRECISE float a = gradientDot(x, y, seed, fx, fy);
  TP_PRECISE float b = gradientDot(x + 1, y, seed, fx - 1.0f, fy);
  TP_PRECISE float c = gradientDot(x, y + 1, seed, fx, fy - 1.0f);
  TP_PRECISE float d = gradientDot(x + 1, y + 1, seed, fx - 1.0f, fy - 1.0f);
  TP_PRECISE float sx = quintic(fx);
  TP_PRECISE float sy = quintic(fy);
  TP_PRECISE float bottom = a + (b - a) * sx;
  TP_PRECISE float top = c + (d - c) * sx;
  return bottom + (top - bottom) * sy;
}

#define TP_NOISE_VALUE_BILINEAR 0u
#define TP_NOISE_VALUE_CUBIC 1u
#define TP_NOISE_GRADIENT 2u

TP_INLINE float noiseOfKind(uint kind, vec2 p, uint seed) {
  if (kind == TP_NOISE_VALUE_BILINEAR) return valueNoiseBilinear(p, seed);
  if (kind == TP_NOISE_VALUE_CUBIC) return valueNoiseCubic(p, seed);
  return gradientNoise(p, seed);
}

// Fractal sum: octave i at frequency 2^i with amplitude persistence^i (each
// octave its own seed), as the original course project's terrain.
TP_INLINE float fractalNoise(uint kind, vec2 p, uint seed, uint octaves, float persistence) {
  TP_PRECISE float sum = 0.0f;
  TP_PRECISE float amplitude = 1.0f;
  TP_PRECISE float frequency = 1.0f;
  for (uint i = 0u; i < octaves; ++i) {
    TP_PRECISE vec2 q = p * frequency;
    sum += amplitude * noiseOfKind(kind, q, seed + i);
    amplitude *= persistence;
    frequency *= 2.0f;
  }
  return sum;
}

struct NoiseSampleParams {
  uint kind;         // TP_NOISE_*
  uint seed;
  uint octaves;
  float persistence;
  uint count;        // number of sample points
  uint pad0, pad1, pad2;
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::NoiseSampleParams) == 32);
#endif

#endif
