#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/vulkan.hpp"

namespace tp::gpu {

struct ReflectedBinding {
  uint32_t binding = 0;
  vk::DescriptorType type = vk::DescriptorType::eStorageBuffer;
};

// What a pipeline layout needs to know about one shader module: its stage,
// the descriptor bindings of set 0, whether it has a push-constant block, and
// the compute local size. Read straight from the SPIR-V, as niagara does.
struct ShaderReflection {
  vk::ShaderStageFlagBits stage = vk::ShaderStageFlagBits::eCompute;
  std::vector<ReflectedBinding> bindings;
  bool pushConstants = false;
  std::array<uint32_t, 3> localSize{1, 1, 1};
};

// Throws on a module that is not SPIR-V, uses a set other than 0, or has a
// descriptor kind tidepool does not bind.
ShaderReflection reflectSpirv(std::span<const uint32_t> code);

}  // namespace tp::gpu
