#pragma once
// The draw and dispatch commands, recorded through helpers that count them:
// the frame's counters (passes, dispatches, draws, workgroups) are what prove
// that a scene pays only for what it needs. Counting is scoped rather than
// threaded through every recording API, so that a dispatch recorded by any
// layer (the water stepper, a pass) is counted the same way.
#include <cstdint>

#include "gpu/vulkan.hpp"

namespace tp::gpu {

struct CommandCounts {
  uint64_t dispatches = 0;
  uint64_t draws = 0;
  uint64_t workgroups = 0;  // compute workgroups launched (indirect ones added when known)
  CommandCounts& operator+=(const CommandCounts& o) {
    dispatches += o.dispatches;
    draws += o.draws;
    workgroups += o.workgroups;
    return *this;
  }
  bool operator==(const CommandCounts&) const = default;
};

// While a CountScope lives, the helpers below add what they record on this
// thread to its counts (scopes nest: the innermost counts).
class CountScope {
 public:
  explicit CountScope(CommandCounts& counts);
  ~CountScope();
  CountScope(const CountScope&) = delete;
  CountScope& operator=(const CountScope&) = delete;

 private:
  CommandCounts* previous_;
};

// The counts of the innermost live scope, or none.
CommandCounts* currentCounts();

void dispatch(const vk::raii::CommandBuffer& cmd, uint32_t groupsX, uint32_t groupsY = 1, uint32_t groupsZ = 1);
// Counts one dispatch; its workgroups are known only on the device, so the
// caller adds them (addWorkgroups) once it has read them back.
void dispatchIndirect(const vk::raii::CommandBuffer& cmd, vk::Buffer args, vk::DeviceSize offset);
void addWorkgroups(uint64_t groups);
void draw(const vk::raii::CommandBuffer& cmd, uint32_t vertexCount, uint32_t instanceCount = 1);
void drawIndexed(const vk::raii::CommandBuffer& cmd, uint32_t indexCount, uint32_t instanceCount = 1);

}  // namespace tp::gpu
