#include "gpu/memory.hpp"

#include "gpu/fault_injection.hpp"

#include <optional>
#include <stdexcept>

namespace tp::gpu {
namespace {

std::optional<uint32_t> findMemoryType(const vk::PhysicalDeviceMemoryProperties& props, uint32_t typeBits,
                                       vk::MemoryPropertyFlags required) {
  for (uint32_t i = 0; i < props.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & required) == required) return i;
  }
  return std::nullopt;
}

bool isFormatDepth(vk::Format format) {
  return format == vk::Format::eD32Sfloat || format == vk::Format::eD16Unorm || format == vk::Format::eD24UnormS8Uint ||
         format == vk::Format::eD32SfloatS8Uint;
}

}  // namespace

vk::raii::DeviceMemory allocateMemory(const Context& ctx, const vk::MemoryRequirements& requirements, MemoryUse use,
                                      const std::string& what) {
  using M = vk::MemoryPropertyFlagBits;
  const auto& props = ctx.memoryProperties();
  std::optional<uint32_t> type;
  switch (use) {
    case MemoryUse::Device:
      type = findMemoryType(props, requirements.memoryTypeBits, M::eDeviceLocal);
      break;
    case MemoryUse::Upload:
      type = findMemoryType(props, requirements.memoryTypeBits, M::eHostVisible | M::eHostCoherent);
      break;
    case MemoryUse::Readback:
      type = findMemoryType(props, requirements.memoryTypeBits, M::eHostVisible | M::eHostCoherent | M::eHostCached);
      if (!type) type = findMemoryType(props, requirements.memoryTypeBits, M::eHostVisible | M::eHostCoherent);
      break;
  }
  if (!type) type = findMemoryType(props, requirements.memoryTypeBits, {});
  if (!type) throw std::runtime_error("no memory type can hold " + what);
  try {
    if (injectedFault() == Fault::OutOfDeviceMemory && requirements.size >= kInjectedOutOfMemoryBytes) {
      throw vk::OutOfDeviceMemoryError("vkAllocateMemory (TIDEPOOL_INJECT_FAULT)");
    }
    return vk::raii::DeviceMemory(
        ctx.device(), vk::MemoryAllocateInfo{.allocationSize = requirements.size, .memoryTypeIndex = *type});
  } catch (const vk::OutOfDeviceMemoryError&) {
    throw std::runtime_error("out of device memory (VK_ERROR_OUT_OF_DEVICE_MEMORY) allocating " +
                             std::to_string(requirements.size) + " bytes for " + what + " on " + ctx.deviceName() +
                             ": try a smaller image or water grid");
  } catch (const vk::OutOfHostMemoryError&) {
    throw std::runtime_error("out of host memory allocating " + std::to_string(requirements.size) + " bytes for " +
                             what);
  }
}

Buffer createBuffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use,
                    const std::string& what) {
  if (size == 0) throw std::runtime_error(what + ": a buffer cannot be empty");
  if ((usage & vk::BufferUsageFlagBits::eStorageBuffer) && size > ctx.limits().maxStorageBufferRange) {
    throw std::runtime_error(what + " needs " + std::to_string(size) +
                             " bytes, over the device's storage buffer limit of " +
                             std::to_string(ctx.limits().maxStorageBufferRange) + " bytes");
  }
  if (injectedFault() == Fault::Leak) {
    (void)(*ctx.device())
        .createBuffer(vk::BufferCreateInfo{.size = 16, .usage = usage}, nullptr, *ctx.device().getDispatcher());
  }
  Buffer b;
  b.size = size;
  b.buffer = vk::raii::Buffer(ctx.device(), vk::BufferCreateInfo{.size = size, .usage = usage});
  b.memory = allocateMemory(ctx, b.buffer.getMemoryRequirements(), use, what);
  b.buffer.bindMemory(*b.memory, 0);
  if (use != MemoryUse::Device) b.mapped = b.memory.mapMemory(0, VK_WHOLE_SIZE);
  return b;
}

Image createImage2D(const Context& ctx, vk::Extent2D extent, vk::Format format, vk::ImageUsageFlags usage,
                    const std::string& what, uint32_t mipLevels) {
  const uint32_t maxDim = ctx.limits().maxImageDimension2D;
  if (extent.width == 0 || extent.height == 0 || extent.width > maxDim || extent.height > maxDim) {
    throw std::runtime_error(what + ": size " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                             " is outside 1.." + std::to_string(maxDim) + " per side on this device");
  }
  Image img;
  img.format = format;
  img.extent = extent;
  img.mipLevels = mipLevels;
  img.aspect = isFormatDepth(format) ? vk::ImageAspectFlagBits::eDepth : vk::ImageAspectFlagBits::eColor;
  img.image = vk::raii::Image(ctx.device(), vk::ImageCreateInfo{
                                                .imageType = vk::ImageType::e2D,
                                                .format = format,
                                                .extent = vk::Extent3D{extent.width, extent.height, 1},
                                                .mipLevels = mipLevels,
                                                .arrayLayers = 1,
                                                .samples = vk::SampleCountFlagBits::e1,
                                                .tiling = vk::ImageTiling::eOptimal,
                                                .usage = usage,
                                                .initialLayout = vk::ImageLayout::eUndefined,
                                            });
  img.memory = allocateMemory(ctx, img.image.getMemoryRequirements(), MemoryUse::Device, what);
  img.image.bindMemory(*img.memory, 0);
  img.view = vk::raii::ImageView(ctx.device(), vk::ImageViewCreateInfo{
                                                   .image = *img.image,
                                                   .viewType = vk::ImageViewType::e2D,
                                                   .format = format,
                                                   .subresourceRange = {img.aspect, 0, mipLevels, 0, 1},
                                               });
  for (uint32_t level = 0; mipLevels > 1 && level < mipLevels; ++level) {
    img.levelViews.emplace_back(ctx.device(), vk::ImageViewCreateInfo{
                                                  .image = *img.image,
                                                  .viewType = vk::ImageViewType::e2D,
                                                  .format = format,
                                                  .subresourceRange = {img.aspect, level, 1, 0, 1},
                                              });
  }
  return img;
}

}  // namespace tp::gpu
