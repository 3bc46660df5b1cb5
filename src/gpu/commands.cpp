#include "gpu/commands.hpp"

namespace tp::gpu {
namespace {
thread_local CommandCounts* tCurrent = nullptr;
}  // namespace

CountScope::CountScope(CommandCounts& counts) : previous_(tCurrent) { tCurrent = &counts; }
CountScope::~CountScope() { tCurrent = previous_; }

CommandCounts* currentCounts() { return tCurrent; }

void dispatch(const vk::raii::CommandBuffer& cmd, uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) {
  cmd.dispatch(groupsX, groupsY, groupsZ);
  if (tCurrent) {
    ++tCurrent->dispatches;
    tCurrent->workgroups += uint64_t(groupsX) * groupsY * groupsZ;
  }
}

void dispatchIndirect(const vk::raii::CommandBuffer& cmd, vk::Buffer args, vk::DeviceSize offset) {
  cmd.dispatchIndirect(args, offset);
  if (tCurrent) ++tCurrent->dispatches;
}

void addWorkgroups(uint64_t groups) {
  if (tCurrent) tCurrent->workgroups += groups;
}

void draw(const vk::raii::CommandBuffer& cmd, uint32_t vertexCount, uint32_t instanceCount) {
  cmd.draw(vertexCount, instanceCount, 0, 0);
  if (tCurrent) ++tCurrent->draws;
}

void drawIndexed(const vk::raii::CommandBuffer& cmd, uint32_t indexCount, uint32_t instanceCount) {
  cmd.drawIndexed(indexCount, instanceCount, 0, 0, 0);
  if (tCurrent) ++tCurrent->draws;
}

}  // namespace tp::gpu
