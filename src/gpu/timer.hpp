#pragma once
#include <string>
#include <vector>

#include "gpu/context.hpp"

namespace tp::gpu {

struct TimedScope {
  std::string name;
  double milliseconds = 0.0;  // NaN where the device has no timestamps
};

// Timestamp queries around named scopes of one command buffer (a timestamp
// around every pass, as niagara does). read() after the submission finished.
class GpuTimer {
 public:
  GpuTimer(const Context& ctx, uint32_t maxScopes);

  void reset(const vk::raii::CommandBuffer& cmd);
  uint32_t begin(const vk::raii::CommandBuffer& cmd, std::string name);
  void end(const vk::raii::CommandBuffer& cmd, uint32_t scope);
  std::vector<TimedScope> read() const;

 private:
  const Context& ctx_;
  uint32_t maxScopes_;
  vk::raii::QueryPool pool_ = nullptr;
  std::vector<std::string> names_;
};

}  // namespace tp::gpu
