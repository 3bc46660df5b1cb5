#include "sim/water_timeline.hpp"

#include <algorithm>

#include "sim/water_scene.hpp"

namespace tp::sim {
namespace {

// The step at which a scheduled drop is applied: where the water is at frame - 1.
uint64_t dropStep(const scene::Drop& drop, const WaterClock& clock) { return clock.stepsAt(drop.frame - 1); }

}  // namespace

double WaterClock::timeAt(uint64_t steps, const scene::Water& water) const {
  return double(frameBase) * water.frameTime + double(steps - stepBase) * waterStep(water);
}

std::vector<size_t> dueDrops(const scene::Water& water, const WaterClock& clock, uint64_t from, uint64_t to,
                             const std::vector<bool>& applied) {
  std::vector<size_t> due;
  for (size_t i = 0; i < water.drops.size(); ++i) {
    const scene::Drop& d = water.drops[i];
    // Frame 0 is the starting state; a frame before the base is in the past.
    if (d.frame == 0 || d.frame - 1 < clock.frameBase) continue;
    if (i < applied.size() && applied[i]) continue;
    const uint64_t step = dropStep(d, clock);
    if (from <= step && step < to) due.push_back(i);
  }
  std::stable_sort(due.begin(), due.end(), [&](size_t a, size_t b) {
    return dropStep(water.drops[a], clock) < dropStep(water.drops[b], clock);
  });
  return due;
}

void recordSceneDrop(const vk::raii::CommandBuffer& cmd, GpuStepper& stepper, const scene::Water& water,
                     const scene::Drop& drop) {
  const glm::vec3 centre = worldToGrid(water, {drop.x, 0.0f, drop.z});
  stepper.recordDrop(cmd, {centre.x, centre.z}, drop.radius, drop.amplitude);
}

void recordWaterRun(const vk::raii::CommandBuffer& cmd, GpuStepper& stepper, const scene::Scene& scene,
                    const WaterClock& clock, uint64_t from, uint64_t to, const std::vector<size_t>& due,
                    const std::vector<SphereMove>& moves) {
  const double pieces = double(to - from);
  // Where move m is after k of its pieces (of one piece when there is no step).
  const auto along = [&](const SphereMove& m, uint64_t k) {
    const glm::vec3 p = k == 0 ? m.from : k >= to - from ? m.to : glm::mix(m.from, m.to, float(double(k) / pieces));
    return worldToGrid(scene.water, p);
  };
  const auto recordMoves = [&](uint64_t k, uint64_t k1, double seconds) {
    for (const SphereMove& m : moves) {
      stepper.recordSphereMove(cmd, along(m, k), along(m, k1), m.radius, scene.water.level, seconds);
    }
  };
  if (to == from) recordMoves(0, 1, 0.0);  // no step to divide them over: at once
  uint64_t at = from;
  // Each run of steps starts at its own time: a moving sphere's path is where
  // it is at that step, as in a run without the drops between. With moves by
  // hand, a run of one step each.
  const auto stepTo = [&](uint64_t step) {
    if (moves.empty()) {
      if (step > at) recordWaterSteps(cmd, stepper, scene, clock.timeAt(at, scene.water), step - at);
      at = step;
      return;
    }
    for (; at < step; ++at) {
      recordMoves(at - from, at - from + 1, waterStep(scene.water));
      recordWaterSteps(cmd, stepper, scene, clock.timeAt(at, scene.water), 1);
    }
  };
  for (const size_t i : due) {
    const scene::Drop& d = scene.water.drops[i];
    stepTo(dropStep(d, clock));
    recordSceneDrop(cmd, stepper, scene.water, d);
  }
  stepTo(to);
}

}  // namespace tp::sim
