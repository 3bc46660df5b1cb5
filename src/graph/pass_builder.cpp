#include "graph/pass_builder.hpp"

#include <stdexcept>

namespace tp::render {

Bindings& Bindings::uniformBuffer(uint32_t binding, const GraphBuffer& buffer, Use use) {
  use_(buffer.ref, use);
  return constantBuffer(binding, *buffer.buffer);
}

Bindings& Bindings::storageBuffer(uint32_t binding, const GraphBuffer& buffer, Use use) {
  use_(buffer.ref, use);
  return constantStorageBuffer(binding, *buffer.buffer);
}

Bindings& Bindings::storageBuffer(uint32_t binding, const SwappingBuffer& buffer, Use use) {
  for (ResourceRef ref : buffer.refs) use_(ref, use);
  entries_.push_back({binding, vk::DescriptorType::eStorageBuffer, buffer.current, nullptr, {}});
  return *this;
}

Bindings& Bindings::storageImage(uint32_t binding, const GraphImage& image, Use use) {
  use_(image.ref, use);
  entries_.push_back({binding, vk::DescriptorType::eStorageImage, {}, image.image, {}});
  return *this;
}

Bindings& Bindings::sampledImage(uint32_t binding, const GraphImage& image, vk::Sampler sampler, Use use) {
  use_(image.ref, use);
  entries_.push_back({binding, vk::DescriptorType::eCombinedImageSampler, {}, image.image, sampler});
  return *this;
}

Bindings& Bindings::constantBuffer(uint32_t binding, const gpu::Buffer& buffer) {
  const gpu::Buffer* b = &buffer;
  entries_.push_back(
      {binding, vk::DescriptorType::eUniformBuffer, [b]() -> const gpu::Buffer& { return *b; }, nullptr, {}});
  return *this;
}

Bindings& Bindings::constantStorageBuffer(uint32_t binding, const gpu::Buffer& buffer) {
  const gpu::Buffer* b = &buffer;
  entries_.push_back(
      {binding, vk::DescriptorType::eStorageBuffer, [b]() -> const gpu::Buffer& { return *b; }, nullptr, {}});
  return *this;
}

void Bindings::bind(const vk::raii::CommandBuffer& cmd, const gpu::Pipeline& pipeline,
                    gpu::DescriptorArena& arena) const {
  gpu::DescriptorWrites writes;
  for (const Entry& e : entries_) {
    if (!gpu::hasBinding(pipeline, e.binding)) continue;  // read by another pipeline of the pass
    switch (e.type) {
      case vk::DescriptorType::eUniformBuffer:
        writes.uniformBuffer(e.binding, e.buffer());
        break;
      case vk::DescriptorType::eStorageBuffer:
        writes.storageBuffer(e.binding, e.buffer());
        break;
      case vk::DescriptorType::eStorageImage:
        writes.storageImage(e.binding, *e.image);
        break;
      default:
        writes.sampledImage(e.binding, *e.image, e.sampler);
        break;
    }
  }
  writes.bind(cmd, pipeline, arena);
}

namespace {

// One use per resource: the same use again is the same declaration; another
// use of the same resource in one pass has no single layout or barrier.
void addUse(std::vector<std::pair<ResourceRef, Use>>& uses, ResourceRef ref, Use use) {
  for (const auto& [r, u] : uses) {
    if (r.index != ref.index) continue;
    if (u == use) return;
    throw std::logic_error("FrameGraph: a pass uses one resource in two ways");
  }
  uses.push_back({ref, use});
}

}  // namespace

Bindings& PassBuilder::bindings() {
  sets_.push_back(std::shared_ptr<Bindings>(new Bindings([this](ResourceRef ref, Use u) { use(ref, u); })));
  return *sets_.back();
}

const gpu::Image& PassBuilder::attach(const GraphImage& image, Use u) {
  use(image.ref, u);
  return *image.image;
}

const gpu::Buffer& PassBuilder::attach(const GraphBuffer& buffer, Use u) {
  use(buffer.ref, u);
  return *buffer.buffer;
}

void PassBuilder::use(ResourceRef ref, Use u) { addUse(uses_, ref, u); }

void PassBuilder::use(const SwappingBuffer& buffer, Use u) {
  for (ResourceRef ref : buffer.refs) use(ref, u);
}

}  // namespace tp::render
