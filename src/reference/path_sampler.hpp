#pragma once
// The path tracer's sample values: a scrambled Sobol sequence, padded. Each
// draw along a path (one value or a pair: a dimension) takes sample `s` of
// the two-dimensional Sobol sequence, the (0,2)-sequence, with its index
// shuffled and its values Owen-scrambled by hashes of the pixel, the
// dimension and the render's seed (Burley, "Practical Hash-based Owen
// Scrambling", JCGT 2020). A pixel's first 2^m samples then cover every
// draw's square evenly, so the error of a smooth integrand falls faster
// than 1/sqrt(N), while each sample alone is uniform: the estimate stays
// unbiased, and another seed gives independent noise. A pixel's samples do
// not depend on the order the threads take them in; a render is the same
// bits every run.
#include <cstdint>
#include <glm/glm.hpp>

#include "reference/pixel_rotation.hpp"

namespace tp::render {

class PathSampler {
 public:
  PathSampler(uint64_t pixel, uint32_t sample, uint32_t seed)
      : key_(hashPixel(hashPixel(uint32_t(pixel) ^ hashPixel(uint32_t(pixel >> 32u) + 0x9e3779b9u)) ^
                       hashPixel(seed + 0x85ebca6bu))),
        sample_(sample) {}

  // Uniform in [0, 1), 24 bits: exact in float.
  float uniform() {
    const uint32_t key = nextDimension();
    return unitFloat(owenScramble(reverseBits(shuffledIndex(key)), hashPixel(key ^ 0x2c1b3c6du)));
  }
  // A pair from one dimension of the (0,2)-sequence: stratified together.
  glm::vec2 uniform2() {
    const uint32_t key = nextDimension();
    const uint32_t index = shuffledIndex(key);
    return {unitFloat(owenScramble(reverseBits(index), hashPixel(key ^ 0x2c1b3c6du))),
            unitFloat(owenScramble(sobolSecond(index), hashPixel(key ^ 0x297a2d39u)))};
  }

 private:
  // The pixel's key for its next dimension.
  uint32_t nextDimension() { return hashPixel(key_ + 0x68e31da4u * ++dimension_); }

  // The sample's index in the sequence, shuffled by a nested scramble of its
  // bits (a permutation of every aligned block of 2^m indices, so that a
  // pixel's first 2^m samples are still the first 2^m points).
  uint32_t shuffledIndex(uint32_t key) const { return owenScramble(sample_, hashPixel(key)); }

  static uint32_t reverseBits(uint32_t x) {
    x = (x << 16u) | (x >> 16u);
    x = ((x & 0x00ff00ffu) << 8u) | ((x & 0xff00ff00u) >> 8u);
    x = ((x & 0x0f0f0f0fu) << 4u) | ((x & 0xf0f0f0f0u) >> 4u);
    x = ((x & 0x33333333u) << 2u) | ((x & 0xccccccccu) >> 2u);
    x = ((x & 0x55555555u) << 1u) | ((x & 0xaaaaaaaau) >> 1u);
    return x;
  }

  // The second dimension of Sobol's sequence (primitive polynomial x + 1):
  // direction numbers 1/2, then each the last xor itself shifted by one.
  static uint32_t sobolSecond(uint32_t index) {
    uint32_t result = 0, direction = 1u << 31u;
    for (; index != 0; index >>= 1u, direction ^= direction >> 1u) {
      if (index & 1u) result ^= direction;
    }
    return result;
  }

  // Owen's scramble of a value in [0, 1) as 32 bits, by a hash in which each
  // bit depends on the seed and the bits below it only (additions and
  // multiplications carry upwards), applied to the bits reversed: each
  // digit is then flipped by a function of the digits above it.
  static uint32_t owenScramble(uint32_t x, uint32_t seed) {
    x = reverseBits(x);
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16u) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return reverseBits(x);
  }

  uint32_t key_ = 0, sample_ = 0, dimension_ = 0;
};

}  // namespace tp::render
