#include "sim/wake_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "gpu/submit.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::sim {
namespace {

constexpr uint64_t kStepsPerSubmit = 256;  // keeps command buffers small on long crossings

}  // namespace

WaterParams waterParams(const WakeCase& c) {
  return {.n = c.grid,
          .extent = c.extent,
          .waveSpeed = c.waveSpeed,
          .damping = c.damping,
          .boundary = c.boundary,
          .maxSlope = c.maxSlope,
          .gridDamping = c.gridDamping,
          .sphereForcing = c.forcing,
          .spreadDepthFactor = c.spreadDepthFactor,
          .widenNearWaveSpeed = c.widenNearWaveSpeed};
}

WakeResult runWake(const gpu::Context& ctx, const WakeCase& c) {
  const WaterParams params = waterParams(c);
  validate(params);
  const double dt = c.frameTime / substepsFor(params, c.frameTime);
  const double speed = c.speedFraction * c.waveSpeed;
  const double y = c.submerged ? -(c.radius + kSubmergedClearance) : 0.0;
  // Along x through the middle, a little off the grid's lines and axis.
  const double x0 = 0.5 * (c.extent - c.crossing), z = 0.5 * c.extent + 0.1;
  // With walls the sphere stops at the crossing's end; round a wrapped grid
  // it moves as far every step, the last one too (a steady motion).
  const bool wrap = c.boundary == Boundary::Wrap;
  const auto centreAt = [&](uint64_t step) {
    const double ahead = x0 + speed * dt * double(step);
    const double x = wrap ? ahead - c.extent * std::floor(ahead / c.extent) : std::min(ahead, x0 + c.crossing);
    return glm::vec3(float(x), float(y), float(z));
  };
  WakeResult r;
  r.steps = uint64_t(std::ceil(c.crossing / (speed * dt)));
  r.dt = dt;
  r.endCentre = centreAt(r.steps);
  GpuStepper stepper(ctx, params, flatState(c.grid), StepKernel::OnePerDispatch);
  const auto start = std::chrono::steady_clock::now();
  for (uint64_t done = 0; done < r.steps; done += kStepsPerSubmit) {
    const uint64_t end = std::min(r.steps, done + kStepsPerSubmit);
    gpu::submitAndWait(
        ctx,
        [&](const vk::raii::CommandBuffer& cmd) {
          for (uint64_t s = done; s < end; ++s) {
            stepper.recordSphereMove(cmd, centreAt(s), centreAt(s + 1), float(c.radius), 0.0f, dt);
            stepper.recordSteps(cmd, 1, dt);
          }
        },
        "wake crossing");
  }
  r.secondsPerStep = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / double(r.steps);
  r.state = stepper.download();
  const double h = params.h();
  double heights = 0.0;
  for (float u : r.state.u) heights += double(u) * h * h;
  r.submergedVolume = sphereCapVolume(c.radius, y, 0.0);
  r.volumeChange = heights;  // the sphere starts and ends as deep, inside the grid: the same submerged volume
  std::vector<WaterlineDisc> hidden;
  if (!c.submerged) hidden.push_back({double(r.endCentre.x), z, c.radius});
  r.measures = measureWake(r.state, c.extent, 0.0, hidden);
  return r;
}

}  // namespace tp::sim
