#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "gpu/memory.hpp"
#include "viewer/swapchain.hpp"
#include "viewer/ui_overlay.hpp"

namespace tp::app {

// Shows the renderer's frames in the window. The renderer reads its LDR
// image back to the host (RenderedFrame::srgb, host-visible memory, a fence
// already waited for); the presenter copies those bytes into an upload
// buffer, then in one submission of its own copies them into an image of the
// frame's size and blits that into the acquired swapchain image. The route
// costs a host copy (about 1 ms at 1280x720, against hundreds of
// milliseconds of rendering on lavapipe) and needs no change to the
// renderer or its frame graph.
//
// The frame keeps its size whatever the window's (or a smaller one under
// dynamic resolution, in the same letterbox) and the blit scales it to the
// window, keeping its aspect (black bars fill the rest). Following each new
// window size would reallocate every target at each step of a drag; with a
// fixed size a resize costs only a new swapchain, and the frame shown is the
// frame `tidepool render` writes at that size.
// Where the frame goes in a window of the given size: as large as fits, its
// aspect kept, centred; the corners of the blit's destination (z 0 and 1).
std::array<vk::Offset3D, 2> letterbox(vk::Extent2D frame, vk::Extent2D window);

class FramePresenter {
 public:
  // `frameSize`: the largest frame, whose aspect the window's letterbox keeps.
  FramePresenter(const gpu::Context& ctx, vk::Extent2D frameSize);
  // Waits for its last submission.
  ~FramePresenter();
  FramePresenter(const FramePresenter&) = delete;
  FramePresenter& operator=(const FramePresenter&) = delete;

  enum class Result {
    Presented,
    PresentedSuboptimal,  // shown, but the swapchain should be recreated
    OutOfDate,            // not shown: recreate the swapchain and show it again
  };
  // `rgba`: the frame's RGBA8 sRGB-encoded pixels, rows top to bottom, of
  // `size` (at most the presenter's frame size: smaller under dynamic
  // resolution, and scaled up to the same letterbox); `overlay`: the panel
  // drawn over it, or none.
  Result show(const Swapchain& swapchain, std::span<const std::uint8_t> rgba, vk::Extent2D size,
              UiOverlay* overlay = nullptr);

 private:
  void record(const Swapchain& swapchain, uint32_t index, vk::Extent2D size, UiOverlay* overlay);

  const gpu::Context& ctx_;
  vk::Extent2D frameSize_;
  gpu::Buffer upload_;
  gpu::Image frame_;
  vk::raii::CommandBuffer cmd_ = nullptr;
  vk::raii::Semaphore acquired_ = nullptr;
  vk::raii::Fence done_ = nullptr;  // the last submission has finished: upload_, cmd_ and acquired_ are free
};

}  // namespace tp::app
