#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

namespace tp::render {

// Base-2 radical inverse (van der Corput): k's bits mirrored about the binary
// point, the second coordinate of the Hammersley points.
inline float radicalInverse(uint32_t k) {
  uint32_t bits = k;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return float(bits) * 2.3283064365386963e-10f;  // 2^-32
}

// The radical inverse of k in `base` (k's digits mirrored about the point):
// base 3 gives the third coordinate of the 3D Hammersley points.
inline float radicalInverseBase(uint32_t k, uint32_t base) {
  float result = 0.0f, digit = 1.0f / float(base);
  for (; k > 0; k /= base, digit /= float(base)) result += float(k % base) * digit;
  return result;
}

// Point i of the n-point Hammersley set in [0,1)^2. The first coordinate is
// the centre of stratum i, as the reference tracer's pixel samples use it.
inline glm::vec2 hammersley(uint32_t i, uint32_t n) { return {(float(i) + 0.5f) / float(n), radicalInverse(i)}; }

// Where sample i of n falls in its pixel (0..1 from the top-left corner): the
// centre for a single sample, the Hammersley points otherwise. The reference
// tracer's rays and the raster's jittered frames use the same points.
inline glm::vec2 pixelSamplePoint(uint32_t i, uint32_t n) { return n == 1 ? glm::vec2(0.5f) : hammersley(i, n); }

// A point of the unit square to the cosine-weighted unit hemisphere about +z
// (Malley's method: the unit disc lifted to the hemisphere), as the SSAO
// kernel and the AO reference sample it.
inline glm::vec3 cosineHemisphere(glm::vec2 u) {
  const float r = std::sqrt(u.x), phi = 6.28318530717958647692f * u.y;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
}

// The orthonormal frame about unit n: any two unit tangents completing it.
inline void tangentFrame(glm::vec3 n, glm::vec3& t, glm::vec3& b) {
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  t = glm::normalize(glm::cross(helper, n));
  b = glm::cross(n, t);
}

// cosineHemisphere's direction about unit n instead of +z.
inline glm::vec3 cosineAbout(glm::vec3 n, glm::vec2 u) {
  glm::vec3 t, b;
  tangentFrame(n, t, b);
  const glm::vec3 local = cosineHemisphere(u);
  return local.x * t + local.y * b + local.z * n;
}

}  // namespace tp::render
