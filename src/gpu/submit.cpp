#include "gpu/submit.hpp"

#include "gpu/fault_injection.hpp"

#include <stdexcept>
#include <string>

namespace tp::gpu {
namespace {

const vk::CommandBufferBeginInfo kBegin{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit};

}  // namespace

Submission::Submission(const Context& ctx, const char* what)
    : ctx_(ctx),
      what_(what),
      buffers_(ctx.device(),
               vk::CommandBufferAllocateInfo{
                   .commandPool = *ctx.commandPool(),
                   .level = vk::CommandBufferLevel::ePrimary,
                   .commandBufferCount = 1,
               }),
      fence_(ctx.device(), vk::FenceCreateInfo{}) {
  cmd().begin(kBegin);
}

void Submission::flush() {
  submitAndWaitPiece();
  ctx_.device().resetFences(*fence_);
  cmd().reset();
  cmd().begin(kBegin);
}

void Submission::finish() { submitAndWaitPiece(); }

void Submission::submitAndWaitPiece() {
  cmd().end();
  vk::CommandBufferSubmitInfo cmdInfo{.commandBuffer = *cmd()};
  try {
    ctx_.queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &cmdInfo}, *fence_);
    // A generous bound: a frame that has not finished in 10 minutes is hung.
    constexpr uint64_t kTimeoutNs = 600ull * 1000 * 1000 * 1000;
    if (ctx_.device().waitForFences(*fence_, VK_TRUE, kTimeoutNs) == vk::Result::eTimeout) {
      throw std::runtime_error(std::string(what_) + " did not finish within 600 s on " + ctx_.deviceName());
    }
    if (injectedFault() == Fault::DeviceLost) throw vk::DeviceLostError("vkWaitForFences (TIDEPOOL_INJECT_FAULT)");
  } catch (const vk::DeviceLostError&) {
    throw std::runtime_error(std::string("the GPU device was lost (VK_ERROR_DEVICE_LOST) during ") + what_ + " on " +
                             ctx_.deviceName() + ": the driver reset it or it hung; no further output was written");
  }
}

void submitAndWait(const Context& ctx, const std::function<void(const vk::raii::CommandBuffer&)>& record,
                   const char* what) {
  Submission submission(ctx, what);
  record(submission.cmd());
  submission.finish();
}

}  // namespace tp::gpu
