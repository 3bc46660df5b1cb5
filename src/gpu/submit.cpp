#include "gpu/submit.hpp"

#include "gpu/fault_injection.hpp"

#include <stdexcept>
#include <string>

namespace tp::gpu {

void submitAndWait(const Context& ctx, const std::function<void(const vk::raii::CommandBuffer&)>& record,
                   const char* what) {
  vk::raii::CommandBuffers buffers(ctx.device(), vk::CommandBufferAllocateInfo{
                                                     .commandPool = *ctx.commandPool(),
                                                     .level = vk::CommandBufferLevel::ePrimary,
                                                     .commandBufferCount = 1,
                                                 });
  const vk::raii::CommandBuffer& cmd = buffers.front();
  cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  record(cmd);
  cmd.end();

  vk::raii::Fence fence(ctx.device(), vk::FenceCreateInfo{});
  vk::CommandBufferSubmitInfo cmdInfo{.commandBuffer = *cmd};
  try {
    ctx.queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &cmdInfo}, *fence);
    // A generous bound: a frame that has not finished in 10 minutes is hung.
    constexpr uint64_t kTimeoutNs = 600ull * 1000 * 1000 * 1000;
    if (ctx.device().waitForFences(*fence, VK_TRUE, kTimeoutNs) == vk::Result::eTimeout) {
      throw std::runtime_error(std::string(what) + " did not finish within 600 s on " + ctx.deviceName());
    }
    if (injectedFault() == Fault::DeviceLost) throw vk::DeviceLostError("vkWaitForFences (TIDEPOOL_INJECT_FAULT)");
  } catch (const vk::DeviceLostError&) {
    throw std::runtime_error(std::string("the GPU device was lost (VK_ERROR_DEVICE_LOST) during ") + what + " on " +
                             ctx.deviceName() + ": the driver reset it or it hung; no further output was written");
  }
}

}  // namespace tp::gpu
