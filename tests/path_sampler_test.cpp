// The path tracer's sample values (reference/path_sampler.hpp) against what
// the scrambled (0,2)-sequence must be, counted here: the first 2^m samples
// of a pixel's dimension put exactly one point in every elementary interval
// of area 2^-m (a (0,m,2)-net), and one value in every 2^-m of [0, 1) for a
// dimension of one value; other pixels, dimensions and seeds scramble the
// points differently.
#include <gtest/gtest.h>

#include <vector>

#include "reference/path_sampler.hpp"

namespace tp::render {
namespace {

constexpr uint32_t kLog2Samples = 8, kSamples = 1u << kLog2Samples;

// The pairs that `dimension` (its draws before it, each a pair) takes for
// samples [first, first + kSamples) of `pixel`.
std::vector<glm::vec2> pairs(uint64_t pixel, uint32_t seed, uint32_t dimension, uint32_t first = 0) {
  std::vector<glm::vec2> out;
  for (uint32_t s = first; s < first + kSamples; ++s) {
    PathSampler sampler(pixel, s, seed);
    for (uint32_t d = 0; d < dimension; ++d) sampler.uniform2();
    out.push_back(sampler.uniform2());
  }
  return out;
}

// Every split of the unit square into 2^a x 2^b boxes with a + b = m has
// one point in each box.
bool isNet(const std::vector<glm::vec2>& points) {
  for (uint32_t a = 0; a <= kLog2Samples; ++a) {
    const uint32_t columns = 1u << a, rows = 1u << (kLog2Samples - a);
    std::vector<int> count(kSamples, 0);
    for (const glm::vec2 p : points) ++count[uint32_t(p.y * float(rows)) * columns + uint32_t(p.x * float(columns))];
    for (const int c : count) {
      if (c != 1) return false;
    }
  }
  return true;
}

TEST(PathSampler, EachDimensionsPairsAreANet) {
  for (const uint64_t pixel : {0ull, 1ull, 14399ull, (1ull << 33u) + 5u}) {
    for (const uint32_t seed : {0u, 1u}) {
      for (const uint32_t dimension : {0u, 1u, 7u, 40u}) {
        EXPECT_TRUE(isNet(pairs(pixel, seed, dimension))) << pixel << " " << seed << " " << dimension;
        // The next aligned block of samples is a net too: a render's passes add whole blocks.
        EXPECT_TRUE(isNet(pairs(pixel, seed, dimension, kSamples)));
      }
    }
  }
}

TEST(PathSampler, EachSingleValueIsStratified) {
  for (const uint32_t draws : {0u, 3u}) {
    std::vector<int> count(kSamples, 0);
    for (uint32_t s = 0; s < kSamples; ++s) {
      PathSampler sampler(77, s, 3);
      for (uint32_t d = 0; d < draws; ++d) sampler.uniform();
      const float u = sampler.uniform();
      ASSERT_GE(u, 0.0f);
      ASSERT_LT(u, 1.0f);
      ++count[uint32_t(u * float(kSamples))];
    }
    for (const int c : count) EXPECT_EQ(c, 1);
  }
}

TEST(PathSampler, PixelsDimensionsAndSeedsScrambleApart) {
  const std::vector<glm::vec2> base = pairs(10, 0, 2);
  for (const auto& other : {pairs(11, 0, 2), pairs(10, 0, 3), pairs(10, 1, 2)}) {
    int same = 0;
    for (uint32_t s = 0; s < kSamples; ++s) same += other[s] == base[s] ? 1 : 0;
    EXPECT_EQ(same, 0);
  }
  // The same pixel, sample and seed: the same values.
  EXPECT_EQ(pairs(10, 0, 2), base);
}

}  // namespace
}  // namespace tp::render
