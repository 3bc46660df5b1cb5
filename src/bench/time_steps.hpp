#pragma once
#include <cstdint>

#include "gpu/timer.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::app {

// Seconds that one submission of `steps` steps of `stepper` takes: GPU
// timestamps around them, the wall clock where the device has none.
double timeSteps(const gpu::Context& ctx, gpu::GpuTimer& timer, sim::GpuStepper& stepper, uint64_t steps, double dt);

}  // namespace tp::app
