#include "viewer/frame_presenter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gpu/barriers.hpp"

namespace tp::app {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
// The submission waits for the acquired image at the transfer stages, and its
// first barrier on that image starts there, so the two chain.
constexpr gpu::Access kAcquired{S::eAllTransfer, A::eNone};
constexpr gpu::Access kClearWrite{S::eClear, A::eTransferWrite};
constexpr gpu::Access kBlitWrite{S::eBlit, A::eTransferWrite};
constexpr gpu::Access kBlitRead{S::eBlit, A::eTransferRead};
// The blit read the renderer's image (a write-after-read: an execution
// dependency is enough).
constexpr gpu::Access kBlitDone{S::eBlit, A::eNone};
// The renderer's image as a frame leaves it: written by the tonemap's compute
// shader, perhaps read by a readback's copy since.
constexpr gpu::Access kRendered{S::eComputeShader | S::eCopy, A::eShaderStorageWrite};
// What the renderer does with the image next: the tonemap writes it, a
// readback copies it.
constexpr gpu::Access kRendererNext{S::eComputeShader | S::eCopy, A::eShaderStorageWrite | A::eTransferRead};
// The panel drawn over the frame (UiOverlay::record).
constexpr gpu::Access kPanelWrite{S::eColorAttachmentOutput, A::eColorAttachmentWrite};

constexpr uint64_t kTimeoutNs = 600ull * 1000 * 1000 * 1000;

}  // namespace

std::array<vk::Offset3D, 2> letterbox(vk::Extent2D frame, vk::Extent2D window) {
  const double scale = std::min(double(window.width) / frame.width, double(window.height) / frame.height);
  const int32_t w = std::clamp(int32_t(std::lround(frame.width * scale)), 1, int32_t(window.width));
  const int32_t h = std::clamp(int32_t(std::lround(frame.height * scale)), 1, int32_t(window.height));
  const int32_t x = (int32_t(window.width) - w) / 2, y = (int32_t(window.height) - h) / 2;
  return {vk::Offset3D{x, y, 0}, vk::Offset3D{x + w, y + h, 1}};
}

FramePresenter::FramePresenter(const gpu::Context& ctx, vk::Extent2D frameSize) : ctx_(ctx), frameSize_(frameSize) {
  const auto features = ctx.physicalDevice().getFormatProperties(vk::Format::eR8G8B8A8Unorm).optimalTilingFeatures;
  if (!(features & vk::FormatFeatureFlagBits::eBlitSrc) ||
      !(features & vk::FormatFeatureFlagBits::eSampledImageFilterLinear)) {
    throw std::runtime_error(ctx.deviceName() + " cannot blit R8G8B8A8 UNORM images with linear filtering");
  }
  vk::raii::CommandBuffers buffers(
      ctx.device(),
      vk::CommandBufferAllocateInfo{
          .commandPool = *ctx.commandPool(), .level = vk::CommandBufferLevel::ePrimary, .commandBufferCount = 1});
  cmd_ = std::move(buffers.front());
  acquired_ = vk::raii::Semaphore(ctx.device(), vk::SemaphoreCreateInfo{});
  done_ = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled});
}

FramePresenter::~FramePresenter() {
  try {
    (void)ctx_.device().waitForFences(*done_, VK_TRUE, kTimeoutNs);
  } catch (const vk::SystemError&) {
    // A lost device: nothing is running any more.
  }
}

FramePresenter::Result FramePresenter::show(const Swapchain& swapchain, const Frame& frame, UiOverlay* overlay) {
  if (frame.size.width > frameSize_.width || frame.size.height > frameSize_.height || frame.size.width == 0 ||
      frame.size.height == 0)
    throw std::logic_error("FramePresenter::show: the frame is not within the size it was made for");
  if (ctx_.device().waitForFences(*done_, VK_TRUE, kTimeoutNs) == vk::Result::eTimeout) {
    throw std::runtime_error("the viewer's last frame did not finish within 600 s on " + ctx_.deviceName());
  }
  uint32_t index = 0;
  bool suboptimal = false;
  try {
    const auto [result, acquired] =
        swapchain.handle().acquireNextImage(std::numeric_limits<uint64_t>::max(), *acquired_, nullptr);
    if (result != vk::Result::eSuccess && result != vk::Result::eSuboptimalKHR) {
      throw std::runtime_error("acquiring a swapchain image returned " + vk::to_string(result));
    }
    index = acquired;
    suboptimal = result == vk::Result::eSuboptimalKHR;
  } catch (const vk::OutOfDateKHRError&) {
    return Result::OutOfDate;  // nothing acquired: the semaphore stays unsignalled
  }
  record(swapchain, index, frame, overlay);
  ctx_.device().resetFences(*done_);
  const vk::SemaphoreSubmitInfo wait{.semaphore = *acquired_, .stageMask = kAcquired.stage};
  const vk::SemaphoreSubmitInfo signal{.semaphore = *swapchain.readyToPresent(index),
                                       .stageMask = vk::PipelineStageFlagBits2::eAllCommands};
  const vk::CommandBufferSubmitInfo cmdInfo{.commandBuffer = *cmd_};
  ctx_.queue().submit2(vk::SubmitInfo2{.waitSemaphoreInfoCount = 1,
                                       .pWaitSemaphoreInfos = &wait,
                                       .commandBufferInfoCount = 1,
                                       .pCommandBufferInfos = &cmdInfo,
                                       .signalSemaphoreInfoCount = 1,
                                       .pSignalSemaphoreInfos = &signal},
                       *done_);
  const vk::SwapchainKHR handle = *swapchain.handle();
  const vk::Semaphore ready = *swapchain.readyToPresent(index);
  try {
    const vk::Result presented = ctx_.queue().presentKHR(vk::PresentInfoKHR{.waitSemaphoreCount = 1,
                                                                            .pWaitSemaphores = &ready,
                                                                            .swapchainCount = 1,
                                                                            .pSwapchains = &handle,
                                                                            .pImageIndices = &index});
    suboptimal = suboptimal || presented == vk::Result::eSuboptimalKHR;
  } catch (const vk::OutOfDateKHRError&) {
    return Result::OutOfDate;
  }
  return suboptimal ? Result::PresentedSuboptimal : Result::Presented;
}

void FramePresenter::record(const Swapchain& swapchain, uint32_t index, const Frame& frame, UiOverlay* overlay) {
  const vk::Image target = swapchain.image(index);
  const vk::Extent2D window = swapchain.extent();
  const auto dst = letterbox(frameSize_, window);
  const bool bars =
      dst[0].x > 0 || dst[0].y > 0 || dst[1].x < int32_t(window.width) || dst[1].y < int32_t(window.height);
  const auto color = vk::ImageAspectFlagBits::eColor;
  using L = vk::ImageLayout;

  cmd_.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  const vk::ImageMemoryBarrier2 toBlit[] = {
      gpu::imageBarrier(frame.image, color, kRendered, frame.layout, kBlitRead, L::eTransferSrcOptimal),
      gpu::imageBarrier(target, color, kAcquired, L::eUndefined, bars ? kClearWrite : kBlitWrite,
                        L::eTransferDstOptimal)};
  gpu::pipelineBarrier(cmd_, {}, toBlit);
  if (bars) {
    const vk::ClearColorValue black{std::array<float, 4>{0.0f, 0.0f, 0.0f, 1.0f}};
    const vk::ImageSubresourceRange all{color, 0, 1, 0, 1};
    cmd_.clearColorImage(target, L::eTransferDstOptimal, black, all);
    const vk::ImageMemoryBarrier2 cleared[] = {
        gpu::imageBarrier(target, color, kClearWrite, L::eTransferDstOptimal, kBlitWrite, L::eTransferDstOptimal)};
    gpu::pipelineBarrier(cmd_, {}, cleared);
  }
  const vk::Extent2D size = frame.size;
  const bool sameSize = dst[1].x - dst[0].x == int32_t(size.width) && dst[1].y - dst[0].y == int32_t(size.height);
  const vk::ImageBlit blit{
      .srcSubresource = {color, 0, 0, 1},
      .srcOffsets = std::array<vk::Offset3D, 2>{vk::Offset3D{0, 0, 0},
                                                vk::Offset3D{int32_t(size.width), int32_t(size.height), 1}},
      .dstSubresource = {color, 0, 0, 1},
      .dstOffsets = dst};
  cmd_.blitImage(frame.image, L::eTransferSrcOptimal, target, L::eTransferDstOptimal, blit,
                 sameSize ? vk::Filter::eNearest : vk::Filter::eLinear);
  // The renderer's image back in its layout, the blit's read finished before
  // the renderer's next writes and copies.
  const vk::ImageMemoryBarrier2 back[] = {
      gpu::imageBarrier(frame.image, color, kBlitDone, L::eTransferSrcOptimal, kRendererNext, frame.layout)};
  gpu::pipelineBarrier(cmd_, {}, back);
  if (overlay) overlay->record(cmd_, swapchain, index);
  // Presentation needs no access of ours: the semaphore signalled after this
  // submission orders the present after the transition.
  const vk::ImageMemoryBarrier2 toPresent[] = {
      overlay
          ? gpu::imageBarrier(target, color, kPanelWrite, L::eColorAttachmentOptimal, gpu::access::none,
                              L::ePresentSrcKHR)
          : gpu::imageBarrier(target, color, kBlitWrite, L::eTransferDstOptimal, gpu::access::none, L::ePresentSrcKHR)};
  gpu::pipelineBarrier(cmd_, {}, toPresent);
  cmd_.end();
}

}  // namespace tp::app
