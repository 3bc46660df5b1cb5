#pragma once
// The path tracer's random numbers: one PCG32 stream per path, its state
// seeded from the pixel, the sample and the render's seed, so that a pixel's
// samples do not depend on the order the threads take them in, and a render
// is the same bits every run.
#include <cstdint>
#include <glm/glm.hpp>

#include "reference/pixel_rotation.hpp"

namespace tp::render {

class PathRandom {
 public:
  PathRandom(uint64_t pixel, uint32_t sample, uint32_t seed) {
    const uint32_t a = hashPixel(uint32_t(pixel) ^ hashPixel(seed + 0x9e3779b9u));
    const uint32_t b = hashPixel(uint32_t(pixel >> 32) + hashPixel(sample * 0x85ebca6bu + seed));
    increment_ = (uint64_t(b) << 1u) | 1u;
    state_ = (uint64_t(a) << 32u | hashPixel(sample)) + increment_;
    next();
  }

  // Uniform in [0, 1), 24 bits: exact in float.
  float uniform() { return float(next() >> 8) * 0x1p-24f; }
  glm::vec2 uniform2() {
    const float u = uniform();
    return {u, uniform()};
  }

 private:
  // O'Neill's PCG32 (XSH RR): a 64-bit LCG, its output permuted.
  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + increment_;
    const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  uint64_t state_ = 0, increment_ = 1;
};

}  // namespace tp::render
