#include "gpu/descriptors.hpp"

#include <array>
#include <stdexcept>

namespace tp::gpu {

DescriptorWrites& DescriptorWrites::add(uint32_t binding, vk::DescriptorType type) {
  writes_.push_back(vk::WriteDescriptorSet{.dstBinding = binding, .descriptorCount = 1, .descriptorType = type});
  return *this;
}

DescriptorWrites& DescriptorWrites::storageBuffer(uint32_t binding, const Buffer& buffer) {
  buffers_.push_back({buffer.handle(), 0, VK_WHOLE_SIZE});
  add(binding, vk::DescriptorType::eStorageBuffer).writes_.back().pBufferInfo = &buffers_.back();
  return *this;
}

DescriptorWrites& DescriptorWrites::uniformBuffer(uint32_t binding, const Buffer& buffer) {
  buffers_.push_back({buffer.handle(), 0, VK_WHOLE_SIZE});
  add(binding, vk::DescriptorType::eUniformBuffer).writes_.back().pBufferInfo = &buffers_.back();
  return *this;
}

DescriptorWrites& DescriptorWrites::storageImage(uint32_t binding, const Image& image) {
  images_.push_back({nullptr, *image.view, vk::ImageLayout::eGeneral});
  add(binding, vk::DescriptorType::eStorageImage).writes_.back().pImageInfo = &images_.back();
  return *this;
}

DescriptorWrites& DescriptorWrites::storageImageLevel(uint32_t binding, const Image& image, uint32_t level) {
  images_.push_back({nullptr, *image.levelViews.at(level), vk::ImageLayout::eGeneral});
  add(binding, vk::DescriptorType::eStorageImage).writes_.back().pImageInfo = &images_.back();
  return *this;
}

DescriptorWrites& DescriptorWrites::sampledImage(uint32_t binding, const Image& image, vk::Sampler sampler) {
  images_.push_back({sampler, *image.view, vk::ImageLayout::eShaderReadOnlyOptimal});
  add(binding, vk::DescriptorType::eCombinedImageSampler).writes_.back().pImageInfo = &images_.back();
  return *this;
}

DescriptorArena::DescriptorArena(const Context& ctx, uint32_t maxSets) : ctx_(ctx), pool_(nullptr) {
  // Each set has a handful of bindings; four of each kind per set is ample.
  std::array<vk::DescriptorPoolSize, 4> sizes{{
      {vk::DescriptorType::eStorageBuffer, 4 * maxSets},
      {vk::DescriptorType::eUniformBuffer, 4 * maxSets},
      {vk::DescriptorType::eStorageImage, 4 * maxSets},
      {vk::DescriptorType::eCombinedImageSampler, 4 * maxSets},
  }};
  pool_ = vk::raii::DescriptorPool(
      ctx.device(), vk::DescriptorPoolCreateInfo{
                        .maxSets = maxSets, .poolSizeCount = uint32_t(sizes.size()), .pPoolSizes = sizes.data()});
}

vk::DescriptorSet DescriptorArena::allocate(vk::DescriptorSetLayout layout) {
  vk::DescriptorSet set;
  vk::DescriptorSetAllocateInfo info{.descriptorPool = *pool_, .descriptorSetCount = 1, .pSetLayouts = &layout};
  vk::Result result = (*ctx_.device()).allocateDescriptorSets(&info, &set);
  if (result != vk::Result::eSuccess) {
    throw std::runtime_error("descriptor arena exhausted (" + vk::to_string(result) + "); reset it between frames");
  }
  return set;
}

void DescriptorArena::reset() { pool_.reset(); }

vk::DescriptorSet DescriptorWrites::allocate(const Pipeline& pipeline, DescriptorArena& arena) {
  for (const auto& b : pipeline.bindings) {
    bool written = false;
    for (const auto& w : writes_) {
      if (w.dstBinding != b.binding) continue;
      if (w.descriptorType != b.type) {
        throw std::runtime_error(pipeline.name + ": binding " + std::to_string(b.binding) + " written as " +
                                 vk::to_string(w.descriptorType) + ", the shader declares " + vk::to_string(b.type));
      }
      written = true;
    }
    if (!written)
      throw std::runtime_error(pipeline.name + ": binding " + std::to_string(b.binding) + " is not written");
  }
  vk::DescriptorSet set = arena.allocate(*pipeline.setLayout);
  for (auto& w : writes_) w.dstSet = set;
  if (!writes_.empty()) arena.device().updateDescriptorSets(writes_, nullptr);
  return set;
}

void DescriptorWrites::bind(const vk::raii::CommandBuffer& cmd, const Pipeline& pipeline, DescriptorArena& arena) {
  if (pipeline.bindings.empty()) return;
  bindSet(cmd, pipeline, allocate(pipeline, arena));
}

void bindSet(const vk::raii::CommandBuffer& cmd, const Pipeline& pipeline, vk::DescriptorSet set) {
  cmd.bindDescriptorSets(pipeline.bindPoint, *pipeline.layout, 0, set, nullptr);
}

}  // namespace tp::gpu
