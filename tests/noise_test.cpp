// The shared noise family: the GPU and the CPU agree to the bit, values stay
// in their stated ranges (measured here), noise is deterministic and continuous.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>

#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/submit.hpp"
#include "gpu/transfer.hpp"
#include "gpu_test.hpp"
#include "shared/noise.h"

namespace tp::test {
namespace {

using shader::fractalNoise;

std::vector<glm::vec2> samplePoints(size_t count) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> coordinate(-300.0f, 300.0f);
  std::vector<glm::vec2> points(count);
  for (auto& p : points) p = {coordinate(rng), coordinate(rng)};
  // Lattice points and their neighbourhoods, negative coordinates included.
  for (int i = 0; i < 64; ++i) points[i] = {float(i - 32), float(31 - i)};
  return points;
}

struct Kind {
  uint32_t id;
  const char* name;
  float low, high;  // stated range of one octave
};
constexpr Kind kKinds[] = {{TP_NOISE_VALUE_BILINEAR, "value bilinear", 0.0f, 1.0f},
                           {TP_NOISE_VALUE_CUBIC, "value cubic", 0.0f, 1.0f},
                           {TP_NOISE_GRADIENT, "gradient", -1.0f, 1.0f},
                           {TP_NOISE_SIMPLEX, "simplex", -1.0f, 1.0f}};

// One corner's term of simplex noise, in double, from its definition.
double simplexTerm(double dx, double dy, double gx, double gy) {
  const double t = std::max(0.5 - dx * dx - dy * dy, 0.0);
  return t * t * t * t * (gx * dx + gy * dy);
}

}  // namespace

using NoiseTest = GpuTest;

TEST_F(NoiseTest, GpuAndCpuAgreeToTheBit) {
  const auto points = samplePoints(4096);
  const uint32_t count = uint32_t(points.size());
  auto pointBuffer = gpu::createBuffer(ctx(), count * sizeof(glm::vec2), vk::BufferUsageFlagBits::eStorageBuffer,
                                       gpu::MemoryUse::Upload, "noise points");
  gpu::uploadToBuffer(ctx(), pointBuffer, points.data(), count * sizeof(glm::vec2));
  auto values = gpu::createBuffer(ctx(), count * sizeof(float),
                                  vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc,
                                  gpu::MemoryUse::Device, "noise values");
  auto pipeline = gpu::createComputePipeline(ctx(), "test_noise.comp", sizeof(shader::NoiseSampleParams));
  gpu::DescriptorArena arena(ctx());
  for (const Kind& kind : kKinds) {
    for (const auto& [octaves, normalised] : {std::pair{1u, 0u}, std::pair{5u, 0u}, std::pair{5u, 1u}}) {
      const shader::NoiseSampleParams params{kind.id, 1234u, octaves, 0.5f, count, normalised, 0, 0};
      gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
        gpu::bindPipeline(cmd, pipeline, params);
        gpu::DescriptorWrites().storageBuffer(0, pointBuffer).storageBuffer(1, values).bind(cmd, pipeline, arena);
        gpu::dispatchCovering(cmd, pipeline, count);
      });
      const auto gpuValues = gpu::readBufferAs<float>(ctx(), values, gpu::access::computeWrite);
      int mismatches = 0;
      for (uint32_t i = 0; i < count; ++i) {
        const float cpu = normalised ? shader::fractalNoise01(kind.id, points[i], 1234u, octaves, 0.5f)
                                     : fractalNoise(kind.id, points[i], 1234u, octaves, 0.5f);
        if (gpuValues[i] != cpu) {
          if (++mismatches <= 3)
            ADD_FAILURE() << kind.name << " octaves " << octaves << " normalised " << normalised << " at ("
                          << points[i].x << ", " << points[i].y << "): GPU " << gpuValues[i] << " CPU " << cpu;
        }
      }
      EXPECT_EQ(mismatches, 0) << kind.name << " octaves " << octaves << " normalised " << normalised;
    }
  }
}

TEST(Noise, RangesAreMeasuredWithinTheStatedBounds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-1000.0f, 1000.0f);
  for (const Kind& kind : kKinds) {
    float low = 1e9f, high = -1e9f;
    for (int i = 0; i < 200000; ++i) {
      const float v = fractalNoise(kind.id, {coordinate(rng), coordinate(rng)}, 99u, 1u, 0.5f);
      low = std::min(low, v);
      high = std::max(high, v);
    }
    EXPECT_GE(low, kind.low) << kind.name;
    EXPECT_LE(high, kind.high) << kind.name;
    // And the range is used: not a constant, not a sliver.
    EXPECT_GT(high - low, 0.5f * (kind.high - kind.low)) << kind.name << " measured [" << low << ", " << high << "]";
    std::printf("%s: measured range [%.4f, %.4f] over 2e5 samples\n", kind.name, low, high);
  }
}

TEST(Noise, DeterministicAndSeeded) {
  const glm::vec2 p(12.34f, -56.78f);
  for (const Kind& kind : kKinds) {
    EXPECT_EQ(fractalNoise(kind.id, p, 5u, 4u, 0.5f), fractalNoise(kind.id, p, 5u, 4u, 0.5f));
    EXPECT_NE(fractalNoise(kind.id, p, 5u, 4u, 0.5f), fractalNoise(kind.id, p, 6u, 4u, 0.5f));
  }
}

// The fractal sums mapped into [0, 1] stay there, for every kind, and use it.
TEST(Noise, NormalisedFractalSumsStayInTheUnitInterval) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-1000.0f, 1000.0f);
  for (const Kind& kind : kKinds) {
    float low = 1e9f, high = -1e9f;
    for (int i = 0; i < 200000; ++i) {
      const float v = shader::fractalNoise01(kind.id, {coordinate(rng), coordinate(rng)}, 5u, 5u, 0.5f);
      low = std::min(low, v);
      high = std::max(high, v);
    }
    EXPECT_GE(low, 0.0f) << kind.name;
    EXPECT_LE(high, 1.0f) << kind.name;
    EXPECT_GT(high - low, 0.4f) << kind.name << " measured [" << low << ", " << high << "]";
    std::printf("%s, 5 octaves, normalised: measured range [%.4f, %.4f] over 2e5 samples\n", kind.name, low, high);
  }
}

// The bound behind kSimplexScale: over the lower triangle of a skewed cell
// (corners (0,0), (1,0), (1,1) in skewed coordinates), and every gradient at
// each corner (the best of gradientDot's eight is |dx| + |dy|, each corner
// choosing its own), the largest sum is 2 / (81 sqrt 3), at the diagonal
// edge's midpoint. Searched on a grid in double, apart from noise.h's code.
TEST(Noise, SimplexSupremumIsAtAnEdgeMidpointAndScalesWithinOne) {
  const double g2 = (3.0 - std::sqrt(3.0)) / 6.0;
  const int corners[3][2] = {{0, 0}, {1, 0}, {1, 1}};
  const int n = 1200;
  double best = 0.0;
  for (int a = 0; a <= n; ++a) {
    for (int b = 0; b <= a; ++b) {
      const double sx = double(a) / n, sy = double(b) / n, unskew = (sx + sy) * g2;
      const double px = sx - unskew, py = sy - unskew;
      double sum = 0.0;
      for (const auto& c : corners) {
        const double cu = (c[0] + c[1]) * g2;
        const double dx = px - (c[0] - cu), dy = py - (c[1] - cu);
        // The best gradient for this corner: the diagonal towards d.
        sum += simplexTerm(dx, dy, dx >= 0 ? 1.0 : -1.0, dy >= 0 ? 1.0 : -1.0);
      }
      best = std::max(best, sum);
    }
  }
  const double analytic = 2.0 / (81.0 * std::sqrt(3.0));
  EXPECT_NEAR(best, analytic, 1e-12) << "grid maximum";
  EXPECT_LE(shader::kSimplexScale * best, 1.0);
  std::printf("simplex: largest corner sum %.7f, times the scale %.5f\n", best, shader::kSimplexScale * best);
}

// No jumps across the triangles' edges: the lines x - y = k (the diagonal of
// a skewed cell) and x + F2 (x + y) = i, y + F2 (x + y) = j (the skewed
// lattice's lines). A step of eps across them changes the noise by at most
// L eps, L a Lipschitz bound from the kernel: one corner's term
// t^4 (g . d), t = 1/2 - r^2, has gradient t^4 g - 8 t^3 (g . d) d, of length
// at most |g| t^3 (t + 8 r^2) = |g| (1/2 - u)^3 (1/2 + 7u) with u = r^2, whose
// largest value is (3/7)^3 at u = 1/14; with |g| <= sqrt 2 and three corners,
// L = 70 * 3 sqrt 2 (3/7)^3 = 23.4.
TEST(Noise, SimplexContinuousAcrossTriangleEdges) {
  const double f2 = (std::sqrt(3.0) - 1.0) / 2.0;
  const double lipschitz = double(shader::kSimplexScale) * 3.0 * std::sqrt(2.0) * std::pow(3.0 / 7.0, 3.0);
  const float eps = 1e-3f;
  struct Line {
    glm::dvec2 normal;  // unit
    glm::dvec2 along;
  };
  const double k = 1.0 / std::sqrt(2.0);
  const double len = std::sqrt((1 + f2) * (1 + f2) + f2 * f2);
  const Line lines[3] = {{{k, -k}, {k, k}},
                         {{(1 + f2) / len, f2 / len}, {-f2 / len, (1 + f2) / len}},
                         {{f2 / len, (1 + f2) / len}, {(1 + f2) / len, -f2 / len}}};
  float worst = 0.0f;
  int pairs = 0;
  for (int which = 0; which < 3; ++which) {
    const Line& line = lines[which];
    for (int offset = -15; offset <= 15; ++offset) {
      // A point on the line: n . p = offset times n's scale for that family.
      const double c = which == 0 ? offset * k : offset / len;
      for (int step = 0; step < 200; ++step) {
        const glm::dvec2 onLine = c * line.normal + (0.0371 * step - 3.7) * line.along;
        const glm::vec2 a(onLine - 0.5 * double(eps) * line.normal), b(onLine + 0.5 * double(eps) * line.normal);
        worst = std::max(worst, std::abs(shader::simplexNoise(a, 3u) - shader::simplexNoise(b, 3u)));
        ++pairs;
      }
    }
  }
  EXPECT_LT(worst, lipschitz * eps) << "over " << pairs << " pairs";
  std::printf("simplex: largest change %.5f over a step of %.0e across edges (bound %.4f), %d pairs\n", worst,
              double(eps), lipschitz * eps, pairs);
}

// No jumps across lattice lines: the change over a step of 1e-3 is bounded by
// a Lipschitz constant times the step (value noise: the largest lattice
// difference, at most 1, times the fade's steepest slope, 1.5 for the cubic;
// gradient noise: a few units).
TEST(Noise, ContinuousAcrossCellBoundaries) {
  const float step = 1e-3f;
  for (const Kind& kind : kKinds) {
    if (kind.id == TP_NOISE_SIMPLEX) continue;  // its cells are triangles: SimplexContinuousAcrossTriangleEdges
    float worst = 0.0f;
    for (int i = -20; i <= 20; ++i) {
      for (float y : {0.25f, 0.5f, 0.9f}) {
        const glm::vec2 a(float(i) - step / 2, y), b(float(i) + step / 2, y);
        worst =
            std::max(worst, std::abs(fractalNoise(kind.id, a, 3u, 1u, 0.5f) - fractalNoise(kind.id, b, 3u, 1u, 0.5f)));
        const glm::vec2 c(y, float(i) - step / 2), d(y, float(i) + step / 2);
        worst =
            std::max(worst, std::abs(fractalNoise(kind.id, c, 3u, 1u, 0.5f) - fractalNoise(kind.id, d, 3u, 1u, 0.5f)));
      }
    }
    EXPECT_LT(worst, 4.0f * step) << kind.name;
  }
}

}  // namespace tp::test
