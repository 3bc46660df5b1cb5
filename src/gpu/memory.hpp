#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/context.hpp"

namespace tp::gpu {

// All device memory is allocated here: one dedicated allocation per buffer or
// image. tidepool makes few, large resources, so no sub-allocator is needed.
enum class MemoryUse {
  Device,    // GPU only; lavapipe's single memory type is host-visible anyway
  Upload,    // host writes, GPU reads
  Readback,  // GPU writes, host reads
};

vk::raii::DeviceMemory allocateMemory(const Context& ctx, const vk::MemoryRequirements& requirements, MemoryUse use,
                                      const std::string& what);

struct Buffer {
  vk::raii::Buffer buffer = nullptr;
  vk::raii::DeviceMemory memory = nullptr;
  vk::DeviceSize size = 0;
  void* mapped = nullptr;  // persistently mapped when the memory is host-visible

  vk::Buffer handle() const { return *buffer; }
};

// Throws with the name and the bound when size exceeds maxStorageBufferRange
// for a storage buffer.
Buffer createBuffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use,
                    const std::string& what);

struct Image {
  vk::raii::Image image = nullptr;
  vk::raii::DeviceMemory memory = nullptr;
  vk::raii::ImageView view = nullptr;
  vk::Format format = vk::Format::eUndefined;
  vk::Extent2D extent;
  vk::ImageAspectFlags aspect;
  uint32_t mipLevels = 1;
  // With more than one level: a view of each level alone, for storage writes
  // (`view` sees them all, for sampling).
  std::vector<vk::raii::ImageView> levelViews;

  vk::Image handle() const { return *image; }
};

// `mipLevels`: level k is extent / 2^k (at least 1 texel); the caller fills them.
Image createImage2D(const Context& ctx, vk::Extent2D extent, vk::Format format, vk::ImageUsageFlags usage,
                    const std::string& what, uint32_t mipLevels = 1);

}  // namespace tp::gpu
