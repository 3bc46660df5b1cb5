#pragma once
#include <deque>
#include <vector>

#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"

namespace tp::gpu {

// Descriptor sets for the commands of one submission, from one pool that is
// reset when the GPU has finished with them: plain descriptor sets, the path
// the synchronization validation of the Debian 12 layer (1.3.239) is known to
// track, and tidepool's tests depend on it seeing every access.
class DescriptorArena {
 public:
  explicit DescriptorArena(const Context& ctx, uint32_t maxSets = 256);
  vk::DescriptorSet allocate(vk::DescriptorSetLayout layout);
  const vk::raii::Device& device() const { return ctx_.device(); }
  // Only once every command buffer using the sets has completed.
  void reset();

 private:
  const Context& ctx_;
  vk::raii::DescriptorPool pool_;
};

// The descriptors of one draw or dispatch. bind() checks that every binding
// the pipeline's shaders declare is written, with the declared type, then
// allocates a set from the arena, writes and binds it.
class DescriptorWrites {
 public:
  DescriptorWrites& storageBuffer(uint32_t binding, const Buffer& buffer);
  DescriptorWrites& uniformBuffer(uint32_t binding, const Buffer& buffer);
  DescriptorWrites& storageImage(uint32_t binding, const Image& image);
  // One mip level of an image made with several (Image::levelViews).
  DescriptorWrites& storageImageLevel(uint32_t binding, const Image& image, uint32_t level);
  DescriptorWrites& sampledImage(uint32_t binding, const Image& image, vk::Sampler sampler);

  // Checks the writes against the pipeline, then allocates and writes a set.
  vk::DescriptorSet allocate(const Pipeline& pipeline, DescriptorArena& arena);
  // allocate() and bindSet() in one.
  void bind(const vk::raii::CommandBuffer& cmd, const Pipeline& pipeline, DescriptorArena& arena);

 private:
  DescriptorWrites& add(uint32_t binding, vk::DescriptorType type);
  std::deque<vk::DescriptorBufferInfo> buffers_;  // deque: pointers stay valid as it grows
  std::deque<vk::DescriptorImageInfo> images_;
  std::vector<vk::WriteDescriptorSet> writes_;
};

// Binds a set made by DescriptorWrites::allocate (sets kept for reuse, like
// the two directions of a ping-pong).
void bindSet(const vk::raii::CommandBuffer& cmd, const Pipeline& pipeline, vk::DescriptorSet set);

}  // namespace tp::gpu
