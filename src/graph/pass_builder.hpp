#pragma once
// Declaring a pass: each resource a pass touches is named once, in the call
// that binds it (a descriptor, an attachment, a copy's end), and that call
// also records the use the frame graph derives barriers from. The two cannot
// drift apart.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "graph/resource_use.hpp"

namespace tp::render {

// An image of the graph with the GPU image behind it.
struct GraphImage {
  ResourceRef ref;
  const gpu::Image* image = nullptr;
  explicit operator bool() const { return image != nullptr; }
};

// A buffer of the graph with the GPU buffer behind it.
struct GraphBuffer {
  ResourceRef ref;
  const gpu::Buffer* buffer = nullptr;
};

// A buffer chosen when the pass records, among several of the graph (the
// water's two state buffers, which swap as it steps): all are used.
struct SwappingBuffer {
  std::vector<ResourceRef> refs;
  std::function<const gpu::Buffer&()> current;
};

// The descriptors of a pass's pipelines, one set. Every binding that names a
// graph resource records its use in the pass. bind() writes the bindings the
// pipeline's shaders declare (a pass whose pipelines differ in what they read
// shares one set), and checks that none it declares is missing.
class Bindings {
 public:
  Bindings& uniformBuffer(uint32_t binding, const GraphBuffer& buffer, Use use);
  Bindings& storageBuffer(uint32_t binding, const GraphBuffer& buffer, Use use);
  Bindings& storageBuffer(uint32_t binding, const SwappingBuffer& buffer, Use use);
  Bindings& storageImage(uint32_t binding, const GraphImage& image, Use use);
  Bindings& sampledImage(uint32_t binding, const GraphImage& image, vk::Sampler sampler, Use use);
  // Data outside the graph: uploaded once, or filled by the host before the
  // frame records (the pool's and the objects' uniforms, the SSAO kernel).
  Bindings& constantBuffer(uint32_t binding, const gpu::Buffer& buffer);
  // The same, read as a storage buffer (too large for a uniform buffer).
  Bindings& constantStorageBuffer(uint32_t binding, const gpu::Buffer& buffer);

  void bind(const vk::raii::CommandBuffer& cmd, const gpu::Pipeline& pipeline, gpu::DescriptorArena& arena) const;

 private:
  friend class PassBuilder;
  explicit Bindings(std::function<void(ResourceRef, Use)> use) : use_(std::move(use)) {}
  struct Entry {
    uint32_t binding;
    vk::DescriptorType type;
    std::function<const gpu::Buffer&()> buffer;  // or
    const gpu::Image* image = nullptr;
    vk::Sampler sampler;
  };
  std::function<void(ResourceRef, Use)> use_;
  std::vector<Entry> entries_;
};

// What FrameGraph::pass hands the function that declares a pass.
class PassBuilder {
 public:
  // A new descriptor set of the pass; it lives as long as the graph.
  Bindings& bindings();
  // An attachment, the end of a copy, or an image the pass binds by itself:
  // the use, and the object to record with.
  const gpu::Image& attach(const GraphImage& image, Use use);
  const gpu::Buffer& attach(const GraphBuffer& buffer, Use use);
  // A resource touched by no descriptor or attachment: the frame uniforms a
  // pass reads through a set of another pass, for instance.
  void use(ResourceRef ref, Use use);
  void use(const SwappingBuffer& buffer, Use use);

 private:
  friend class FrameGraph;
  PassBuilder() = default;
  std::vector<std::pair<ResourceRef, Use>> uses_;
  std::vector<std::shared_ptr<Bindings>> sets_;
};

}  // namespace tp::render
