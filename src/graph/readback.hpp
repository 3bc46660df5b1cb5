#pragma once
// What the host reads after a frame: the pass that copies an image into a
// buffer, and the copies out of the buffer's mapped memory.
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/context.hpp"
#include "graph/frame_graph.hpp"

namespace tp::render {

// A buffer of the graph the host reads after a frame. Requesting `ref`
// records the passes that fill it.
struct Readback {
  Readback(const gpu::Context& ctx, FrameGraph& graph, const std::string& name, vk::DeviceSize bytes);
  Readback(const Readback&) = delete;  // the graph holds its address
  gpu::Buffer buffer;
  GraphBuffer ref;
};

// Transfer: an image copied into the readback's buffer.
void declareReadback(FrameGraph& graph, const PassKind& kind, const GraphImage& image, const Readback& readback);

// The first `count` values of a read-back buffer.
std::vector<float> readFloats(const gpu::Buffer& buffer, size_t count);
std::vector<std::uint8_t> readBytes(const gpu::Buffer& buffer, size_t count);
// Half floats (a 16-bit float image's texels) widened to float.
std::vector<float> readHalves(const gpu::Buffer& buffer, size_t count);

}  // namespace tp::render
