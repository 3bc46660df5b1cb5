#include "gpu/spirv_reflect.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

namespace tp::gpu {
namespace {

// SPIR-V opcodes and enumerants used here (SPIR-V specification, section 3).
enum Op : uint32_t {
  OpEntryPoint = 15,
  OpExecutionMode = 16,
  OpTypeImage = 25,
  OpTypeSampler = 26,
  OpTypeSampledImage = 27,
  OpTypeArray = 28,
  OpTypeRuntimeArray = 29,
  OpTypeStruct = 30,
  OpTypePointer = 32,
  OpConstant = 43,
  OpSpecConstant = 50,
  OpVariable = 59,
  OpDecorate = 71,
  OpExecutionModeId = 331,
};
constexpr uint32_t kMagic = 0x07230203;
constexpr uint32_t kDecorationBlock = 2;
constexpr uint32_t kDecorationBufferBlock = 3;
constexpr uint32_t kDecorationBinding = 33;
constexpr uint32_t kDecorationDescriptorSet = 34;
constexpr uint32_t kExecutionModeLocalSize = 17;
constexpr uint32_t kExecutionModeLocalSizeId = 38;  // what glslang emits for SPIR-V 1.6
enum StorageClass : uint32_t {
  UniformConstant = 0,
  Uniform = 2,
  PushConstant = 9,
  StorageBuffer = 12,
};

struct Id {
  uint32_t opcode = 0;
  uint32_t typeId = 0;        // pointee for pointers, element for arrays, image for sampled image
  uint32_t storageClass = 0;  // pointers and variables
  uint32_t binding = ~0u;
  uint32_t set = ~0u;
  bool block = false;
  bool bufferBlock = false;
  uint32_t imageSampled = 0;  // OpTypeImage: 1 sampled, 2 storage
  uint32_t imageDim = 0;
  uint32_t constant = 0;  // OpConstant / OpSpecConstant (default) value, first word
};

vk::ShaderStageFlagBits stageOf(uint32_t executionModel) {
  switch (executionModel) {
    case 0:
      return vk::ShaderStageFlagBits::eVertex;
    case 4:
      return vk::ShaderStageFlagBits::eFragment;
    case 5:
      return vk::ShaderStageFlagBits::eCompute;
    default:
      throw std::runtime_error("SPIR-V entry point of unsupported execution model " + std::to_string(executionModel));
  }
}

vk::DescriptorType descriptorType(const std::vector<Id>& ids, const Id& variable) {
  uint32_t type = ids[variable.typeId].typeId;  // variable -> pointer -> pointee
  while (ids[type].opcode == OpTypeArray || ids[type].opcode == OpTypeRuntimeArray) type = ids[type].typeId;
  const Id& t = ids[type];
  constexpr uint32_t kDimBuffer = 5;
  switch (t.opcode) {
    case OpTypeStruct:
      if (variable.storageClass == StorageBuffer || t.bufferBlock) return vk::DescriptorType::eStorageBuffer;
      if (variable.storageClass == Uniform && t.block) return vk::DescriptorType::eUniformBuffer;
      break;
    case OpTypeSampledImage:
      return vk::DescriptorType::eCombinedImageSampler;
    case OpTypeSampler:
      return vk::DescriptorType::eSampler;
    case OpTypeImage:
      if (t.imageDim == kDimBuffer) break;
      return t.imageSampled == 2 ? vk::DescriptorType::eStorageImage : vk::DescriptorType::eSampledImage;
    default:
      break;
  }
  throw std::runtime_error("SPIR-V binding " + std::to_string(variable.binding) +
                           " has a descriptor kind tidepool does not bind");
}

// What the types, constants, decorations and variables of one instruction
// say of its ids.
void recordId(std::vector<Id>& ids, uint32_t opcode, const uint32_t* w, uint32_t count) {
  auto checkId = [&](uint32_t id) {
    if (id >= ids.size()) throw std::runtime_error("SPIR-V id out of bounds");
    return id;
  };
  switch (opcode) {
    case OpConstant:
    case OpSpecConstant:
      if (count >= 4) ids[checkId(w[2])].constant = w[3];
      break;
    case OpDecorate: {
      Id& id = ids[checkId(w[1])];
      if (w[2] == kDecorationBinding && count >= 4) id.binding = w[3];
      if (w[2] == kDecorationDescriptorSet && count >= 4) id.set = w[3];
      if (w[2] == kDecorationBlock) id.block = true;
      if (w[2] == kDecorationBufferBlock) id.bufferBlock = true;
      break;
    }
    case OpTypeStruct:
    case OpTypeSampler:
      ids[checkId(w[1])].opcode = opcode;
      break;
    case OpTypeImage: {
      Id& id = ids[checkId(w[1])];
      id.opcode = opcode;
      id.imageDim = w[3];
      id.imageSampled = w[7];
      break;
    }
    case OpTypeSampledImage:
    case OpTypeArray:
    case OpTypeRuntimeArray: {
      Id& id = ids[checkId(w[1])];
      id.opcode = opcode;
      id.typeId = checkId(w[2]);
      break;
    }
    case OpTypePointer: {
      Id& id = ids[checkId(w[1])];
      id.opcode = opcode;
      id.storageClass = w[2];
      id.typeId = checkId(w[3]);
      break;
    }
    case OpVariable: {
      Id& id = ids[checkId(w[2])];
      id.opcode = opcode;
      id.typeId = checkId(w[1]);
      id.storageClass = w[3];
      break;
    }
    default:
      break;
  }
}

// The module's descriptor bindings (set 0) and whether it has push constants.
void collectBindings(const std::vector<Id>& ids, ShaderReflection& out) {
  for (const Id& id : ids) {
    if (id.opcode != OpVariable) continue;
    if (id.storageClass == PushConstant) {
      out.pushConstants = true;
      continue;
    }
    if (id.storageClass != UniformConstant && id.storageClass != Uniform && id.storageClass != StorageBuffer) continue;
    if (id.binding == ~0u) continue;
    if (id.set != 0)
      throw std::runtime_error("SPIR-V binding in descriptor set " + std::to_string(id.set) +
                               "; tidepool uses set 0 only");
    out.bindings.push_back({id.binding, descriptorType(ids, id)});
  }
}

}  // namespace

ShaderReflection reflectSpirv(std::span<const uint32_t> code) {
  if (code.size() < 5 || code[0] != kMagic) throw std::runtime_error("not a SPIR-V module (bad magic number)");
  const uint32_t bound = code[3];
  std::vector<Id> ids(bound);
  ShaderReflection out;
  bool haveEntry = false;
  std::optional<std::array<uint32_t, 3>> localSizeIds;

  for (size_t at = 5; at < code.size();) {
    const uint32_t opcode = code[at] & 0xffff;
    const uint32_t count = code[at] >> 16;
    if (count == 0 || at + count > code.size()) throw std::runtime_error("truncated SPIR-V module");
    const uint32_t* w = &code[at];
    auto checkId = [&](uint32_t id) {
      if (id >= bound) throw std::runtime_error("SPIR-V id out of bounds");
      return id;
    };
    switch (opcode) {
      case OpEntryPoint:
        if (haveEntry) throw std::runtime_error("SPIR-V module with more than one entry point");
        out.stage = stageOf(w[1]);
        haveEntry = true;
        break;
      case OpExecutionMode:
        if (w[2] == kExecutionModeLocalSize && count >= 6) out.localSize = {w[3], w[4], w[5]};
        break;
      case OpExecutionModeId:
        if (w[2] == kExecutionModeLocalSizeId && count >= 6)
          localSizeIds = {checkId(w[3]), checkId(w[4]), checkId(w[5])};
        break;
      default:
        recordId(ids, opcode, w, count);
        break;
    }
    at += count;
  }
  if (!haveEntry) throw std::runtime_error("SPIR-V module without an entry point");
  if (localSizeIds) {
    for (int i = 0; i < 3; ++i) out.localSize[i] = ids[(*localSizeIds)[i]].constant;
  }

  collectBindings(ids, out);
  std::sort(out.bindings.begin(), out.bindings.end(),
            [](const ReflectedBinding& a, const ReflectedBinding& b) { return a.binding < b.binding; });
  return out;
}

}  // namespace tp::gpu
