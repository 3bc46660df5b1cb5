// A compute round trip against a CPU answer, and proof that the harness can
// fail: a deliberately missing barrier must be reported by synchronization
// validation (on lavapipe the numbers come out right regardless).
#include <gtest/gtest.h>

#include <numeric>

#include "gpu/barriers.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/submit.hpp"
#include "gpu/transfer.hpp"
#include "gpu_test.hpp"

namespace tp::test {
namespace {

struct SaxpyPush {
  float a;
  uint32_t n;
};

constexpr uint32_t kCount = 1000;  // not a multiple of the local size: the edge guard matters

struct Saxpy {
  explicit Saxpy(const gpu::Context& ctx)
      : pipeline(gpu::createComputePipeline(ctx, "test_saxpy.comp", sizeof(SaxpyPush))),
        x(gpu::createBuffer(ctx, kCount * 4,
                            vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc,
                            gpu::MemoryUse::Upload, "x")),
        y(gpu::createBuffer(ctx, kCount * 4,
                            vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc,
                            gpu::MemoryUse::Upload, "y")),
        descriptors(ctx) {
    for (uint32_t i = 0; i < kCount; ++i) {
      xs.push_back(0.37f * float(i) - 11.0f);
      ys.push_back(1.0f / float(i + 1));
    }
    gpu::uploadToBuffer(ctx, x, xs.data(), kCount * 4);
    gpu::uploadToBuffer(ctx, y, ys.data(), kCount * 4);
  }
  // in = a * in + out
  void dispatch(const vk::raii::CommandBuffer& cmd, float a, const gpu::Buffer& in, const gpu::Buffer& out) {
    gpu::bindPipeline(cmd, pipeline, SaxpyPush{a, kCount});
    gpu::DescriptorWrites().storageBuffer(0, in).storageBuffer(1, out).bind(cmd, pipeline, descriptors);
    gpu::dispatchCovering(cmd, pipeline, kCount);
  }
  gpu::Pipeline pipeline;
  gpu::Buffer x, y;
  gpu::DescriptorArena descriptors;
  std::vector<float> xs, ys;
};

}  // namespace

using ComputeTest = GpuTest;

TEST_F(ComputeTest, RoundTripMatchesCpu) {
  Saxpy s(ctx());
  EXPECT_EQ(s.pipeline.localSize[0], 64u);
  // Two dependent steps with the barrier between them. a = 2 makes a*x exact,
  // so fused and unfused multiply-add round the same way and equality is exact.
  gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
    s.dispatch(cmd, 2.0f, s.x, s.y);
    auto barrier = gpu::bufferBarrier(
        s.y.handle(), {vk::PipelineStageFlagBits2::eComputeShader, vk::AccessFlagBits2::eShaderStorageWrite},
        {vk::PipelineStageFlagBits2::eComputeShader,
         vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eShaderStorageWrite});
    gpu::pipelineBarrier(cmd, std::span(&barrier, 1));
    s.dispatch(cmd, 2.0f, s.x, s.y);
  });
  auto got = gpu::readBufferAs<float>(ctx(), s.y, gpu::access::computeWrite);
  ASSERT_EQ(got.size(), kCount);
  for (uint32_t i = 0; i < kCount; ++i) {
    float once = 2.0f * s.xs[i] + s.ys[i];
    float twice = 2.0f * s.xs[i] + once;
    ASSERT_EQ(got[i], twice) << "at " << i;
  }
}

TEST_F(ComputeTest, MissingBarrierIsReportedBySynchronizationValidation) {
  Saxpy s(ctx());
  // The second dispatch reads y (as its input) right after the first wrote it,
  // with no barrier between: a read-after-write hazard.
  gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
    s.dispatch(cmd, 2.0f, s.x, s.y);
    s.dispatch(cmd, 2.0f, s.y, s.x);
  });
  ctx().device().waitIdle();
  auto& log = ctx().validationLog();
  EXPECT_TRUE(log.contains("SYNC-HAZARD-READ-AFTER-WRITE"))
      << "synchronization validation missed the hazard; messages:\n"
      << joined(log.messages());
  log.clear();  // the hazard was the point of this test
}

}  // namespace tp::test
