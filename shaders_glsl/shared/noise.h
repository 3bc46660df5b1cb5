// The noise family, one text for C++ and GLSL: an integer hash, value noise
// (bilinear and cubic), gradient noise (Perlin, quintic fade), simplex noise
// and fractal sums. Only integer operations, multiplies, adds and floor, each written so
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

// Simplex noise (Perlin 2001, in Gustavson's 2D form): the plane cut into
// equilateral triangles by skewing the square lattice with F2 = (sqrt 3 - 1)/2
// and back with G2 = (3 - sqrt 3)/6. Each corner of the point's triangle adds
// (1/2 - r^2)^4 (g . d) with gradientDot's eight gradients; the kernel's
// radius sqrt(1/2) is the triangle's height, so a corner's kernel ends (with
// three zero derivatives) on the far edge: continuous, no other corner reaches in.
const float kSimplexSkew = 0.36602540378443865f;    // F2 = (sqrt(3) - 1) / 2
const float kSimplexUnskew = 0.21132486540518713f;  // G2 = (3 - sqrt(3)) / 6
const float kSimplexRadius2 = 0.5f;                 // the kernel's squared radius
// Scales the sum into [-1, 1]. The largest |sum| over every gradient choice is
// 2 / (81 sqrt 3) = 0.0142556, at the midpoint of an edge with the diagonal
// gradient at both ends (t = 1/3, g . d = 1/sqrt 3 each; the third corner's t = 0):
// a grid search over the triangle finds no larger (tests/noise_test.cpp). So
// the classic scale 70 bounds simplex noise by 140 / (81 sqrt 3) = 0.99789.
const float kSimplexScale = 70.0f;

TP_INLINE float simplexCorner(int x, int y, uint seed, float dx, float dy) {
  TP_PRECISE float t = kSimplexRadius2 - dx * dx - dy * dy;
  if (t <= 0.0f) return 0.0f;
  TP_PRECISE float t2 = t * t;
  TP_PRECISE float weighted = t2 * t2 * gradientDot(x, y, seed, dx, dy);
  return weighted;
}

TP_INLINE float simplexNoise(vec2 p, uint seed) {
  TP_PRECISE float skew = (p.x + p.y) * kSimplexSkew;
  TP_PRECISE float sx = p.x + skew;
  TP_PRECISE float sy = p.y + skew;
  int i = int(floor(sx)), j = int(floor(sy));
  TP_PRECISE float unskew = float(i + j) * kSimplexUnskew;
  TP_PRECISE float x0 = p.x - (float(i) - unskew);
  TP_PRECISE float y0 = p.y - (float(j) - unskew);
  // The lower (x0 > y0) or upper triangle of the skewed cell.
  int i1 = x0 > y0 ? 1 : 0;
  int j1 = 1 - i1;
  TP_PRECISE float x1 = x0 - float(i1) + kSimplexUnskew;
  TP_PRECISE float y1 = y0 - float(j1) + kSimplexUnskew;
  TP_PRECISE float x2 = x0 - 1.0f + 2.0f * kSimplexUnskew;
  TP_PRECISE float y2 = y0 - 1.0f + 2.0f * kSimplexUnskew;
  TP_PRECISE float sum = simplexCorner(i, j, seed, x0, y0) + simplexCorner(i + i1, j + j1, seed, x1, y1) +
                         simplexCorner(i + 1, j + 1, seed, x2, y2);
  TP_PRECISE float scaled = kSimplexScale * sum;
  return scaled;
}

#define TP_NOISE_VALUE_BILINEAR 0u
#define TP_NOISE_VALUE_CUBIC 1u
#define TP_NOISE_GRADIENT 2u
#define TP_NOISE_SIMPLEX 3u

TP_INLINE float noiseOfKind(uint kind, vec2 p, uint seed) {
  if (kind == TP_NOISE_VALUE_BILINEAR) return valueNoiseBilinear(p, seed);
  if (kind == TP_NOISE_VALUE_CUBIC) return valueNoiseCubic(p, seed);
  if (kind == TP_NOISE_SIMPLEX) return simplexNoise(p, seed);
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

// The fractal sum mapped into [0, 1]: divided by the sum of the amplitudes,
// and the signed kinds (gradient, simplex: [-1, 1]) shifted and halved.
TP_INLINE float fractalNoise01(uint kind, vec2 p, uint seed, uint octaves, float persistence) {
  TP_PRECISE float total = 0.0f;
  TP_PRECISE float amplitude = 1.0f;
  for (uint i = 0u; i < octaves; ++i) {
    total += amplitude;
    amplitude *= persistence;
  }
  TP_PRECISE float f = fractalNoise(kind, p, seed, octaves, persistence) / total;
  if (kind == TP_NOISE_GRADIENT || kind == TP_NOISE_SIMPLEX) f = 0.5f * f + 0.5f;
  return f;
}

struct NoiseSampleParams {
  uint kind;         // TP_NOISE_*
  uint seed;
  uint octaves;
  float persistence;
  uint count;        // number of sample points
  uint normalised;   // 1: fractalNoise01, 0: fractalNoise
  uint pad1, pad2;
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::NoiseSampleParams) == 32);
#endif

#endif
