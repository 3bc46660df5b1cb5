#pragma once
#include <array>
#include <cstdint>

#include "gpu/context.hpp"
#include "viewer/swapchain.hpp"
#include "viewer/ui_overlay.hpp"

namespace tp::app {

// Where the frame goes in a window of the given size: as large as fits, its
// aspect kept, centred; the corners of the blit's destination (z 0 and 1).
std::array<vk::Offset3D, 2> letterbox(vk::Extent2D frame, vk::Extent2D window);

// Shows the renderer's frames in the window: in one submission of its own on
// the renderer's queue, the renderer's tonemapped image (left on the GPU,
// FrameRequest::present) is blitted into the acquired swapchain image, with
// no copy through the host. The submission waits for the acquired image and
// signals the one the present waits for.
//
// The frame keeps its size whatever the window's (or a smaller one under
// dynamic resolution, in the same letterbox) and the blit scales it to the
// window, keeping its aspect (black bars fill the rest). Following each new
// window size would reallocate every target at each step of a drag; with a
// fixed size a resize costs only a new swapchain, and the frame shown is the
// frame `tidepool render` writes at that size.
class FramePresenter {
 public:
  // `frameSize`: the largest frame, whose aspect the window's letterbox keeps.
  FramePresenter(const gpu::Context& ctx, vk::Extent2D frameSize);

  // A frame to show: an RGBA8 image holding sRGB-encoded values, on the
  // presenter's queue, of `size` (at most the presenter's frame size: smaller
  // under dynamic resolution, and scaled up to the same letterbox), its last
  // write a compute shader's (or a copy read it since), in `layout`, in which
  // the presenter leaves it.
  struct Frame {
    vk::Image image;
    vk::Extent2D size;
    vk::ImageLayout layout;
  };
  // Waits for its last submission.
  ~FramePresenter();
  FramePresenter(const FramePresenter&) = delete;
  FramePresenter& operator=(const FramePresenter&) = delete;

  enum class Result {
    Presented,
    PresentedSuboptimal,  // shown, but the swapchain should be recreated
    OutOfDate,            // not shown: recreate the swapchain and show it again
  };
  // `overlay`: the panel drawn over the frame, or none.
  Result show(const Swapchain& swapchain, const Frame& frame, UiOverlay* overlay = nullptr);

 private:
  void record(const Swapchain& swapchain, uint32_t index, const Frame& frame, UiOverlay* overlay);

  const gpu::Context& ctx_;
  vk::Extent2D frameSize_;
  vk::raii::CommandBuffer cmd_ = nullptr;
  vk::raii::Semaphore acquired_ = nullptr;
  vk::raii::Fence done_ = nullptr;  // the last submission has finished: cmd_ and acquired_ are free
};

}  // namespace tp::app
