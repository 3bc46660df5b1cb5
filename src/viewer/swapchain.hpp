#pragma once
#include <cstdint>
#include <vector>

#include "gpu/context.hpp"

namespace tp::app {

// The window's swapchain: FIFO present (always there, no tearing), an 8-bit
// UNORM format the frame's bytes are copied into as they are (the renderer's
// LDR image is already sRGB encoded), images written by transfers (the frame)
// and as colour attachments (the panel over it).
// Recreated on resize and when presentation says it is out of date.
class Swapchain {
 public:
  // Throws when the device cannot present to the surface, or the surface
  // offers no usable format. `framebuffer` is used where the surface leaves
  // the size to the application.
  Swapchain(const gpu::Context& ctx, const vk::raii::SurfaceKHR& surface, vk::Extent2D framebuffer);
  // Waits for the queue to be idle: a present may still read the images and
  // wait on the semaphores.
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // Makes a new swapchain at the surface's current size (from the old one).
  // Returns false, keeping the old one, while the surface has no area
  // (minimised). The caller waits for the queue to be idle first.
  bool recreate(vk::Extent2D framebuffer);

  const vk::raii::SwapchainKHR& handle() const { return swapchain_; }
  vk::Extent2D extent() const { return extent_; }
  vk::Format format() const { return format_; }
  vk::Image image(uint32_t index) const { return images_.at(index); }
  vk::ImageView view(uint32_t index) const { return *views_.at(index); }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  // Counts the swapchains made: what was made for the images of an earlier
  // one (framebuffers) is stale when it changes.
  uint64_t generation() const { return generation_; }
  // Signalled when image `index` is ready to present: one per image, so a
  // semaphore is used again only once its image has been acquired again.
  const vk::raii::Semaphore& readyToPresent(uint32_t index) const { return readyToPresent_.at(index); }

 private:
  bool create(vk::Extent2D framebuffer);

  const gpu::Context& ctx_;
  const vk::raii::SurfaceKHR& surface_;
  vk::SurfaceFormatKHR surfaceFormat_;
  vk::Format format_ = vk::Format::eUndefined;
  vk::Extent2D extent_;
  vk::raii::SwapchainKHR swapchain_ = nullptr;
  std::vector<vk::Image> images_;
  std::vector<vk::raii::ImageView> views_;
  uint64_t generation_ = 0;
  std::vector<vk::raii::Semaphore> readyToPresent_;
};

}  // namespace tp::app
