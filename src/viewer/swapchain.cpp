#include "viewer/swapchain.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tp::app {
namespace {

// The frame's bytes are sRGB-encoded RGBA8: a UNORM swapchain image shows
// them as they are (an _SRGB one would encode them again in the blit). Either
// channel order will do: the blit swizzles.
vk::SurfaceFormatKHR chooseFormat(const gpu::Context& ctx, const vk::raii::SurfaceKHR& surface) {
  const auto formats = ctx.physicalDevice().getSurfaceFormatsKHR(*surface);
  std::string offered;
  for (vk::Format wanted : {vk::Format::eB8G8R8A8Unorm, vk::Format::eR8G8B8A8Unorm}) {
    for (const auto& f : formats) {
      if (f.format != wanted || f.colorSpace != vk::ColorSpaceKHR::eSrgbNonlinear) continue;
      const auto features = ctx.physicalDevice().getFormatProperties(f.format).optimalTilingFeatures;
      if (features & vk::FormatFeatureFlagBits::eBlitDst) return f;
    }
  }
  for (const auto& f : formats) offered += (offered.empty() ? "" : ", ") + vk::to_string(f.format);
  throw std::runtime_error("the window's surface offers no B8G8R8A8 or R8G8B8A8 UNORM sRGB-nonlinear format that " +
                           ctx.deviceName() + " can blit to (offered: " + offered + ")");
}

}  // namespace

Swapchain::Swapchain(const gpu::Context& ctx, const vk::raii::SurfaceKHR& surface, vk::Extent2D framebuffer)
    : ctx_(ctx), surface_(surface) {
  if (!ctx.physicalDevice().getSurfaceSupportKHR(ctx.queueFamily(), *surface)) {
    throw std::runtime_error(ctx.deviceName() + "'s queue cannot present to the window's surface");
  }
  surfaceFormat_ = chooseFormat(ctx, surface);
  format_ = surfaceFormat_.format;
  if (!create(framebuffer)) throw std::runtime_error("the window has no area to show frames in");
}

Swapchain::~Swapchain() {
  try {
    ctx_.queue().waitIdle();
  } catch (const vk::SystemError&) {
    // A lost device: there is nothing left to wait for.
  }
}

bool Swapchain::recreate(vk::Extent2D framebuffer) { return create(framebuffer); }

bool Swapchain::create(vk::Extent2D framebuffer) {
  const auto caps = ctx_.physicalDevice().getSurfaceCapabilitiesKHR(*surface_);
  vk::Extent2D extent = caps.currentExtent;
  if (extent.width == std::numeric_limits<uint32_t>::max()) {
    extent.width = std::clamp(framebuffer.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(framebuffer.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0) return false;
  // The frame is blitted in, the panel drawn over it.
  const vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eColorAttachment;
  if ((caps.supportedUsageFlags & usage) != usage) {
    throw std::runtime_error(
        "the window's swapchain images cannot be transfer destinations and colour attachments on " + ctx_.deviceName());
  }
  uint32_t count = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
  vk::CompositeAlphaFlagBitsKHR alpha = vk::CompositeAlphaFlagBitsKHR::eOpaque;
  if (!(caps.supportedCompositeAlpha & alpha)) alpha = vk::CompositeAlphaFlagBitsKHR::eInherit;
  vk::raii::SwapchainKHR next(ctx_.device(), vk::SwapchainCreateInfoKHR{
                                                 .surface = *surface_,
                                                 .minImageCount = count,
                                                 .imageFormat = surfaceFormat_.format,
                                                 .imageColorSpace = surfaceFormat_.colorSpace,
                                                 .imageExtent = extent,
                                                 .imageArrayLayers = 1,
                                                 .imageUsage = usage,
                                                 .imageSharingMode = vk::SharingMode::eExclusive,
                                                 .preTransform = caps.currentTransform,
                                                 .compositeAlpha = alpha,
                                                 .presentMode = vk::PresentModeKHR::eFifo,
                                                 .clipped = VK_TRUE,
                                                 .oldSwapchain = *swapchain_,
                                             });
  views_.clear();
  swapchain_ = std::move(next);  // the old one is destroyed here, retired by the new one
  const auto images = swapchain_.getImages();
  images_.assign(images.begin(), images.end());
  for (vk::Image image : images_) {
    views_.emplace_back(ctx_.device(),
                        vk::ImageViewCreateInfo{.image = image,
                                                .viewType = vk::ImageViewType::e2D,
                                                .format = format_,
                                                .subresourceRange = {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}});
  }
  ++generation_;
  extent_ = extent;
  readyToPresent_.clear();
  for (size_t i = 0; i < images_.size(); ++i) readyToPresent_.emplace_back(ctx_.device(), vk::SemaphoreCreateInfo{});
  return true;
}

}  // namespace tp::app
