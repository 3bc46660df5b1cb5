#pragma once
#include <cstring>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/barriers.hpp"
#include "gpu/memory.hpp"

namespace tp::gpu {

// Host to buffer: a memcpy where the buffer is mapped, else through a staging
// buffer and a copy, followed by a barrier that makes it visible to all later work.
void uploadToBuffer(const Context& ctx, const Buffer& buffer, const void* data, size_t bytes);

// A buffer made for `data` and filled with it (uploadToBuffer; transfer-dst usage added).
Buffer createFilledBuffer(const Context& ctx, const void* data, size_t bytes, vk::BufferUsageFlags usage, MemoryUse use,
                          const std::string& what);

template <typename T>
Buffer createFilledBuffer(const Context& ctx, const std::vector<T>& data, vk::BufferUsageFlags usage, MemoryUse use,
                          const std::string& what) {
  return createFilledBuffer(ctx, data.data(), data.size() * sizeof(T), usage, use, what);
}

// Buffer to host, through a readback buffer and a copy, with the transfer-to-host
// barrier. `src` is where the buffer was last written (e.g. access::computeWrite).
std::vector<std::byte> readBuffer(const Context& ctx, const Buffer& buffer, Access src);

template <typename T>
std::vector<T> readBufferAs(const Context& ctx, const Buffer& buffer, Access src) {
  auto bytes = readBuffer(ctx, buffer, src);
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

// Records the copy of the whole of `from` into `to`, of the same extent and
// format: `from` in transfer-source layout, `to` in transfer-destination.
void recordImageCopy(const vk::raii::CommandBuffer& cmd, const Image& from, const Image& to);
// The same, over the pixels [lo, hi) alone.
void recordImageCopy(const vk::raii::CommandBuffer& cmd, const Image& from, const Image& to, glm::uvec2 lo,
                     glm::uvec2 hi);

}  // namespace tp::gpu
