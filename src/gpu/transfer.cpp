#include "gpu/transfer.hpp"

#include "gpu/barriers.hpp"
#include "gpu/submit.hpp"

namespace tp::gpu {

void uploadToBuffer(const Context& ctx, const Buffer& buffer, const void* data, size_t bytes) {
  if (bytes > buffer.size)
    throw std::runtime_error("upload of " + std::to_string(bytes) + " bytes into a buffer of " +
                             std::to_string(buffer.size));
  if (buffer.mapped) {
    std::memcpy(buffer.mapped, data, bytes);
    return;  // host-coherent; the queue submission that follows makes host writes visible
  }
  Buffer staging = createBuffer(ctx, bytes, vk::BufferUsageFlagBits::eTransferSrc, MemoryUse::Upload, "upload staging");
  std::memcpy(staging.mapped, data, bytes);
  submitAndWait(
      ctx,
      [&](const vk::raii::CommandBuffer& cmd) {
        cmd.copyBuffer(staging.handle(), buffer.handle(), vk::BufferCopy{0, 0, bytes});
        // Later submissions come later in submission order, so this covers them.
        auto after = bufferBarrier(buffer.handle(), access::transferWrite, access::anyAccess);
        pipelineBarrier(cmd, std::span(&after, 1));
      },
      "buffer upload");
}

Buffer createFilledBuffer(const Context& ctx, const void* data, size_t bytes, vk::BufferUsageFlags usage, MemoryUse use,
                          const std::string& what) {
  Buffer buffer = createBuffer(ctx, bytes, usage | vk::BufferUsageFlagBits::eTransferDst, use, what);
  uploadToBuffer(ctx, buffer, data, bytes);
  return buffer;
}

std::vector<std::byte> readBuffer(const Context& ctx, const Buffer& buffer, Access src) {
  Buffer readback =
      createBuffer(ctx, buffer.size, vk::BufferUsageFlagBits::eTransferDst, MemoryUse::Readback, "readback");
  submitAndWait(
      ctx,
      [&](const vk::raii::CommandBuffer& cmd) {
        auto before = bufferBarrier(buffer.handle(), src, access::transferRead);
        pipelineBarrier(cmd, std::span(&before, 1));
        cmd.copyBuffer(buffer.handle(), readback.handle(), vk::BufferCopy{0, 0, buffer.size});
        auto after = bufferBarrier(readback.handle(), access::transferWrite, access::hostRead);
        pipelineBarrier(cmd, std::span(&after, 1));
      },
      "buffer readback");
  std::vector<std::byte> out(buffer.size);
  std::memcpy(out.data(), readback.mapped, buffer.size);
  return out;
}

void recordImageCopy(const vk::raii::CommandBuffer& cmd, const Image& from, const Image& to) {
  recordImageCopy(cmd, from, to, glm::uvec2(0u), glm::uvec2(from.extent.width, from.extent.height));
}

void recordImageCopy(const vk::raii::CommandBuffer& cmd, const Image& from, const Image& to, glm::uvec2 lo,
                     glm::uvec2 hi) {
  const vk::Offset3D at{int32_t(lo.x), int32_t(lo.y), 0};
  cmd.copyImage(from.handle(), vk::ImageLayout::eTransferSrcOptimal, to.handle(), vk::ImageLayout::eTransferDstOptimal,
                vk::ImageCopy{.srcSubresource = {from.aspect, 0, 0, 1},
                              .srcOffset = at,
                              .dstSubresource = {to.aspect, 0, 0, 1},
                              .dstOffset = at,
                              .extent = {hi.x - lo.x, hi.y - lo.y, 1}});
}

}  // namespace tp::gpu
