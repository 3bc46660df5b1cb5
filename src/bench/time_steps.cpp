#include "bench/time_steps.hpp"

#include <chrono>
#include <cmath>

#include "gpu/submit.hpp"

namespace tp::app {

double timeSteps(const gpu::Context& ctx, gpu::GpuTimer& timer, sim::GpuStepper& stepper, uint64_t steps, double dt) {
  const auto start = std::chrono::steady_clock::now();
  gpu::submitAndWait(
      ctx,
      [&](const vk::raii::CommandBuffer& cmd) {
        timer.reset(cmd);
        const uint32_t scope = timer.begin(cmd, "steps");
        stepper.recordSteps(cmd, steps, dt);
        timer.end(cmd, scope);
      },
      "benchmark");
  const double seconds = timer.read().front().milliseconds * 1e-3;
  if (!std::isnan(seconds)) return seconds;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tp::app
