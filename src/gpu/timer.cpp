#include "gpu/timer.hpp"

#include <cmath>
#include <stdexcept>

namespace tp::gpu {

GpuTimer::GpuTimer(const Context& ctx, uint32_t maxScopes) : ctx_(ctx), maxScopes_(maxScopes) {
  if (ctx.timestampsSupported()) {
    pool_ = vk::raii::QueryPool(
        ctx.device(), vk::QueryPoolCreateInfo{.queryType = vk::QueryType::eTimestamp, .queryCount = 2 * maxScopes});
  }
}

void GpuTimer::reset(const vk::raii::CommandBuffer& cmd) {
  names_.clear();
  if (*pool_) cmd.resetQueryPool(*pool_, 0, 2 * maxScopes_);
}

uint32_t GpuTimer::begin(const vk::raii::CommandBuffer& cmd, std::string name) {
  if (names_.size() >= maxScopes_)
    throw std::runtime_error("GpuTimer: more than " + std::to_string(maxScopes_) + " scopes");
  const uint32_t scope = uint32_t(names_.size());
  names_.push_back(std::move(name));
  if (*pool_) cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eAllCommands, *pool_, 2 * scope);
  return scope;
}

void GpuTimer::end(const vk::raii::CommandBuffer& cmd, uint32_t scope) {
  if (*pool_) cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eAllCommands, *pool_, 2 * scope + 1);
}

std::vector<TimedScope> GpuTimer::read() const {
  std::vector<TimedScope> out;
  if (names_.empty()) return out;
  std::vector<uint64_t> ticks(2 * names_.size(), 0);
  if (*pool_) {
    auto [result, values] =
        pool_.getResults<uint64_t>(0, uint32_t(ticks.size()), ticks.size() * sizeof(uint64_t), sizeof(uint64_t),
                                   vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
    (void)result;
    ticks = std::move(values);
  }
  const double period = ctx_.limits().timestampPeriod;  // ns per tick
  for (size_t i = 0; i < names_.size(); ++i) {
    double ms = *pool_ ? double(ticks[2 * i + 1] - ticks[2 * i]) * period * 1e-6 : std::nan("");
    out.push_back({names_[i], ms});
  }
  return out;
}

}  // namespace tp::gpu
