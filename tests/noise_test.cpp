// The shared noise family: the GPU and the CPU agree to the bit, values stay
// in their stated ranges (measured here), noise is deterministic and continuous.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

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
                           {TP_NOISE_GRADIENT, "gradient", -1.0f, 1.0f}};

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
    for (uint32_t octaves : {1u, 5u}) {
      const shader::NoiseSampleParams params{kind.id, 1234u, octaves, 0.5f, count, 0, 0, 0};
      gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
        gpu::bindPipeline(cmd, pipeline, params);
        gpu::DescriptorWrites().storageBuffer(0, pointBuffer).storageBuffer(1, values).bind(cmd, pipeline, arena);
        gpu::dispatchCovering(cmd, pipeline, count);
      });
      const auto gpuValues = gpu::readBufferAs<float>(ctx(), values, gpu::access::computeWrite);
      int mismatches = 0;
      for (uint32_t i = 0; i < count; ++i) {
        const float cpu = fractalNoise(kind.id, points[i], 1234u, octaves, 0.5f);
        if (gpuValues[i] != cpu) {
          if (++mismatches <= 3) ADD_FAILURE() << kind.name << " octaves " << octaves << " at (" << points[i].x << ", "
                                               << points[i].y << "): GPU " << gpuValues[i] << " CPU " << cpu;
        }
      }
      EXPECT_EQ(mismatches, 0) << kind.name << " octaves " << octaves;
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

// No jumps across lattice lines: the change over a step of 1e-3 is bounded by
// a Lipschitz constant times the step (value noise: the largest lattice
// difference, at most 1, times the fade's steepest slope, 1.5 for the cubic;
// gradient noise: a few units).
TEST(Noise, ContinuousAcrossCellBoundaries) {
  const float step = 1e-3f;
  for (const Kind& kind : kKinds) {
    float worst = 0.0f;
    for (int i = -20; i <= 20; ++i) {
      for (float y : {0.25f, 0.5f, 0.9f}) {
        const glm::vec2 a(float(i) - step / 2, y), b(float(i) + step / 2, y);
        worst = std::max(worst, std::abs(fractalNoise(kind.id, a, 3u, 1u, 0.5f) - fractalNoise(kind.id, b, 3u, 1u, 0.5f)));
        const glm::vec2 c(y, float(i) - step / 2), d(y, float(i) + step / 2);
        worst = std::max(worst, std::abs(fractalNoise(kind.id, c, 3u, 1u, 0.5f) - fractalNoise(kind.id, d, 3u, 1u, 0.5f)));
      }
    }
    EXPECT_LT(worst, 4.0f * step) << kind.name;
  }
}

}  // namespace tp::test
