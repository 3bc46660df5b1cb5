#pragma once
// Runs a test-only compute shader at points: binding 0 the points, 1 the
// values (valuesPerPoint vec4s a point), 2 the pool's uniforms where the
// shader takes them (`pool` not null), the count pushed. What the GPU
// computed, for the tests to hold against the CPU's.
#include <optional>
#include <string>
#include <vector>

#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/submit.hpp"
#include "gpu/transfer.hpp"
#include "shared/pool.h"

namespace tp::test {

template <typename Point>
std::vector<glm::vec4> shaderAtPoints(const gpu::Context& ctx, const std::string& shaderName,
                                      const std::vector<Point>& points, uint32_t valuesPerPoint,
                                      const shader::PoolParams* pool = nullptr) {
  const uint32_t count = uint32_t(points.size());
  auto pointBuffer =
      gpu::createFilledBuffer(ctx, points, vk::BufferUsageFlagBits::eStorageBuffer, gpu::MemoryUse::Upload, "points");
  std::optional<gpu::Buffer> poolBuffer;
  if (pool)
    poolBuffer.emplace(gpu::createFilledBuffer(ctx, pool, sizeof(*pool), vk::BufferUsageFlagBits::eUniformBuffer,
                                               gpu::MemoryUse::Upload, "pool uniforms"));
  auto values = gpu::createBuffer(ctx, valuesPerPoint * count * sizeof(glm::vec4),
                                  vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc,
                                  gpu::MemoryUse::Device, "values");
  auto pipeline = gpu::createComputePipeline(ctx, shaderName, sizeof(uint32_t));
  gpu::DescriptorArena arena(ctx);
  gpu::submitAndWait(ctx, [&](const vk::raii::CommandBuffer& cmd) {
    gpu::bindPipeline(cmd, pipeline, count);
    gpu::DescriptorWrites writes;
    writes.storageBuffer(0, pointBuffer).storageBuffer(1, values);
    if (poolBuffer) writes.uniformBuffer(2, *poolBuffer);
    writes.bind(cmd, pipeline, arena);
    gpu::dispatchCovering(cmd, pipeline, count);
  });
  return gpu::readBufferAs<glm::vec4>(ctx, values, gpu::access::computeWrite);
}

// The same for a shader of the pool's shared functions.
template <typename Point>
std::vector<glm::vec4> poolShaderAtPoints(const gpu::Context& ctx, const std::string& shaderName,
                                          const std::vector<Point>& points, const shader::PoolParams& pool,
                                          uint32_t valuesPerPoint) {
  return shaderAtPoints(ctx, shaderName, points, valuesPerPoint, &pool);
}

}  // namespace tp::test
