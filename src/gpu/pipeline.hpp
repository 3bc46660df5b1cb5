#pragma once
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "gpu/context.hpp"
#include "gpu/spirv_reflect.hpp"

namespace tp::gpu {

// Specialization constants for one shader, filled from C++ (kernel sizes and
// the like), so shaders carry no tunable numbers of their own.
class Specialization {
 public:
  template <typename T>
  Specialization& set(uint32_t constantId, T value) {
    static_assert(sizeof(T) == 4, "specialization constants are 32-bit here");
    entries_.push_back({constantId, uint32_t(data_.size()), sizeof(T)});
    data_.resize(data_.size() + sizeof(T));
    std::memcpy(data_.data() + data_.size() - sizeof(T), &value, sizeof(T));
    return *this;
  }
  vk::SpecializationInfo info() const {
    return {uint32_t(entries_.size()), entries_.data(), data_.size(), data_.data()};
  }
  bool empty() const { return entries_.empty(); }

 private:
  std::vector<vk::SpecializationMapEntry> entries_;
  std::vector<uint8_t> data_;
};

struct PipelineBinding {
  uint32_t binding;
  vk::DescriptorType type;
  vk::ShaderStageFlags stages;
};

// A pipeline with its layout. Descriptor bindings (set 0)
// come from SPIR-V reflection; the push-constant size comes from the C++
// struct shared with the shader (sizeof), the one declared place.
struct Pipeline {
  std::string name;
  vk::PipelineBindPoint bindPoint = vk::PipelineBindPoint::eCompute;
  std::vector<PipelineBinding> bindings;
  vk::ShaderStageFlags pushStages;
  uint32_t pushSize = 0;
  std::array<uint32_t, 3> localSize{1, 1, 1};
  vk::raii::DescriptorSetLayout setLayout = nullptr;
  vk::raii::PipelineLayout layout = nullptr;
  vk::raii::Pipeline pipeline = nullptr;
};

Pipeline createComputePipeline(const Context& ctx, const std::string& shader, uint32_t pushSize,
                               const Specialization& specialization = {});

struct GraphicsPipelineDesc {
  std::string vertexShader;
  std::string fragmentShader;
  uint32_t pushSize = 0;
  std::vector<vk::Format> colorFormats;
  vk::Format depthFormat = vk::Format::eUndefined;
  bool depthTest = false;
  bool depthWrite = false;
  vk::PrimitiveTopology topology = vk::PrimitiveTopology::eTriangleList;
  vk::CullModeFlags cullMode = vk::CullModeFlagBits::eNone;
  bool additive = false;                       // blend: destination + source (accumulating targets)
  bool colorWrites = true;                     // false: the colour targets are left as they are (depth alone)
  Specialization fragmentSpecialization = {};  // the fragment shader's specialization constants
};

Pipeline createGraphicsPipeline(const Context& ctx, const GraphicsPipelineDesc& desc);

// Whether the pipeline's shaders declare descriptor `binding` (passes that
// share a draw between pipelines write only what each one reads).
inline bool hasBinding(const Pipeline& p, uint32_t binding) {
  for (const auto& b : p.bindings) {
    if (b.binding == binding) return true;
  }
  return false;
}

// Binds the pipeline and pushes its constants (if any).
template <typename Push>
void bindPipeline(const vk::raii::CommandBuffer& cmd, const Pipeline& p, const Push& push) {
  cmd.bindPipeline(p.bindPoint, *p.pipeline);
  if (sizeof(Push) != p.pushSize) {
    throw std::runtime_error(p.name + ": push constants of " + std::to_string(sizeof(Push)) + " bytes, layout has " +
                             std::to_string(p.pushSize));
  }
  cmd.pushConstants<Push>(*p.layout, p.pushStages, 0, push);
}

// Dispatches enough groups to cover (x, y, z) invocations; shaders guard the edge.
void dispatchCovering(const vk::raii::CommandBuffer& cmd, const Pipeline& p, uint32_t x, uint32_t y = 1,
                      uint32_t z = 1);

}  // namespace tp::gpu
