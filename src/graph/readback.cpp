#include "graph/readback.hpp"

#include <cstring>
#include <glm/gtc/packing.hpp>

namespace tp::render {

Readback::Readback(const gpu::Context& ctx, FrameGraph& graph, const std::string& name, vk::DeviceSize bytes)
    : buffer(gpu::createBuffer(ctx, bytes, vk::BufferUsageFlagBits::eTransferDst, gpu::MemoryUse::Readback, name)),
      ref(graph.buffer(name, buffer)) {}

void declareReadback(FrameGraph& graph, const PassKind& kind, const GraphImage& image, const Readback& readback) {
  graph.pass(kind, [image, &readback](PassBuilder& pass) {
    const gpu::Image& from = pass.attach(image, Use::TransferRead);
    const gpu::Buffer& to = pass.attach(readback.ref, Use::TransferWrite);
    return [&from, &to](PassContext& pc) {
      const vk::BufferImageCopy region{
          .bufferOffset = 0,
          .bufferRowLength = 0,
          .bufferImageHeight = 0,
          .imageSubresource = {from.aspect, 0, 0, 1},
          .imageOffset = {0, 0, 0},
          .imageExtent = {from.extent.width, from.extent.height, 1},
      };
      pc.cmd.copyImageToBuffer(from.handle(), vk::ImageLayout::eTransferSrcOptimal, to.handle(), region);
    };
  });
}

std::vector<float> readFloats(const gpu::Buffer& buffer, size_t count) {
  std::vector<float> values(count);
  std::memcpy(values.data(), buffer.mapped, count * sizeof(float));
  return values;
}

std::vector<std::uint8_t> readBytes(const gpu::Buffer& buffer, size_t count) {
  std::vector<std::uint8_t> values(count);
  std::memcpy(values.data(), buffer.mapped, count);
  return values;
}

std::vector<float> readHalves(const gpu::Buffer& buffer, size_t count) {
  std::vector<float> values(count);
  const auto* halves = static_cast<const std::uint16_t*>(buffer.mapped);
  for (size_t i = 0; i < count; ++i) values[i] = glm::unpackHalf1x16(halves[i]);
  return values;
}

}  // namespace tp::render
