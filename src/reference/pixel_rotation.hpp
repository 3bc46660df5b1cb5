#pragma once
// A pixel's Cranley-Patterson rotation, for the reference's sample sets: every
// pixel uses the same low-discrepancy points shifted modulo 1 by its own
// offset, so neighbouring pixels' errors are uncorrelated (noise, not a
// pattern) while each stays a low-discrepancy set.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace tp::render {

// A 32-bit integer hash with good avalanche (Wellons' "lowbias32" constants):
// neighbouring pixel indices get unrelated offsets.
inline uint32_t hashPixel(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// [0, 1), exact in float.
inline float unitFloat(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

// The offset of pixel `pixel` (its index in the image), in [0, 1)^2.
inline glm::vec2 pixelRotation(size_t pixel) {
  const uint32_t a = hashPixel(uint32_t(pixel)), b = hashPixel(a);
  return {unitFloat(a), unitFloat(b)};
}

// u + offset modulo 1, for u and offset in [0, 1).
inline float wrapUnit(float u) { return u >= 1.0f ? u - 1.0f : u; }

}  // namespace tp::render
