#pragma once
#include <span>

#include "gpu/vulkan.hpp"

namespace tp::gpu {

// synchronization2 barriers with exact stage and access masks. Every barrier
// in tidepool is built by one of these and issued by pipelineBarrier().

struct Access {
  vk::PipelineStageFlags2 stage;
  vk::AccessFlags2 access;
};

inline vk::BufferMemoryBarrier2 bufferBarrier(vk::Buffer buffer, Access src, Access dst) {
  return vk::BufferMemoryBarrier2{
      .srcStageMask = src.stage,
      .srcAccessMask = src.access,
      .dstStageMask = dst.stage,
      .dstAccessMask = dst.access,
      .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .buffer = buffer,
      .offset = 0,
      .size = VK_WHOLE_SIZE,
  };
}

inline vk::ImageMemoryBarrier2 imageBarrier(vk::Image image, vk::ImageAspectFlags aspect, Access src,
                                            vk::ImageLayout oldLayout, Access dst, vk::ImageLayout newLayout) {
  return vk::ImageMemoryBarrier2{
      .srcStageMask = src.stage,
      .srcAccessMask = src.access,
      .dstStageMask = dst.stage,
      .dstAccessMask = dst.access,
      .oldLayout = oldLayout,
      .newLayout = newLayout,
      .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .image = image,
      .subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS},
  };
}

inline void pipelineBarrier(const vk::raii::CommandBuffer& cmd, std::span<const vk::BufferMemoryBarrier2> buffers,
                            std::span<const vk::ImageMemoryBarrier2> images = {}) {
  if (buffers.empty() && images.empty()) return;
  cmd.pipelineBarrier2(vk::DependencyInfo{
      .bufferMemoryBarrierCount = uint32_t(buffers.size()),
      .pBufferMemoryBarriers = buffers.data(),
      .imageMemoryBarrierCount = uint32_t(images.size()),
      .pImageMemoryBarriers = images.data(),
  });
}

// A global memory barrier, for when every resource written at src is read at dst
// (a ping-pong step writes one buffer and reads the other).
inline void stageBarrier(const vk::raii::CommandBuffer& cmd, Access src, Access dst) {
  vk::MemoryBarrier2 barrier{
      .srcStageMask = src.stage, .srcAccessMask = src.access, .dstStageMask = dst.stage, .dstAccessMask = dst.access};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &barrier});
}

namespace access {
using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
inline constexpr Access none{S::eNone, A::eNone};
inline constexpr Access computeWrite{S::eComputeShader, A::eShaderStorageWrite};
inline constexpr Access computeRead{S::eComputeShader, A::eShaderStorageRead};
inline constexpr Access transferWrite{S::eCopy, A::eTransferWrite};
inline constexpr Access transferRead{S::eCopy, A::eTransferRead};
inline constexpr Access hostRead{S::eHost, A::eHostRead};
inline constexpr Access indirectRead{S::eDrawIndirect, A::eIndirectCommandRead};
inline constexpr Access anyAccess{S::eAllCommands, A::eMemoryRead | A::eMemoryWrite};
}  // namespace access

}  // namespace tp::gpu
