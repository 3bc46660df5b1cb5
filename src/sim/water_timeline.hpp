#pragma once
#include <cstdint>
#include <vector>

#include "gpu/vulkan.hpp"
#include "scene/scene.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::sim {

// When things happen to the water: its clock, and the drops a scene schedules
// on it (scene::Drop::frame >= 1). The renderer and simulateWater() both step
// through here, so a renderer of a scene and a run of its water apply each
// drop at the same step.

// Steps and frames: the water was at frame `frameBase` after `stepBase` steps
// and has taken `substeps` steps per frame since (the renderer re-bases it when
// the water's dynamics change; a run from the start has both bases 0).
struct WaterClock {
  uint32_t frameBase = 0;
  uint64_t stepBase = 0;
  uint32_t substeps = 1;
  // The steps done at `frame` (not before frameBase).
  uint64_t stepsAt(uint32_t frame) const { return stepBase + uint64_t(frame - frameBase) * substeps; }
  // The frame reached after `steps` (whole frames: the water is stepped a frame at a time).
  uint32_t frameAt(uint64_t steps) const { return frameBase + uint32_t((steps - stepBase) / substeps); }
  // Scene time (seconds) after `steps`, for the paths of the spheres.
  double timeAt(uint64_t steps, const scene::Water& water) const;
};

// The scheduled drops of `water` (indices into water.drops, in the order they
// are applied: by step, then as the scene lists them) due in the steps from
// `from` to `to`: drop k is due at stepsAt(k - 1) when from <= that < to, so a
// run that takes no step applies none. Those marked in `applied` (indices past
// its end count as not applied), and those whose frame lies before the
// clock's base (in the past), are left out.
std::vector<size_t> dueDrops(const scene::Water& water, const WaterClock& clock, uint64_t from, uint64_t to,
                             const std::vector<bool>& applied);

// Records one of the scene's drops into the water.
void recordSceneDrop(const vk::raii::CommandBuffer& cmd, GpuStepper& stepper, const scene::Water& water,
                     const scene::Drop& drop);

// A sphere moved by hand (the viewer's drag) from one world position to
// another within a frame.
struct SphereMove {
  glm::vec3 from, to;
  float radius;
};

// Records the steps from `from` to `to` with the drops `due` (dueDrops'
// answer for those steps) between them, each at its step: runs of
// recordWaterSteps, each from its own start time. The `moves` are divided
// over the steps, an equal piece before each (all at once if there is none).
void recordWaterRun(const vk::raii::CommandBuffer& cmd, GpuStepper& stepper, const scene::Scene& scene,
                    const WaterClock& clock, uint64_t from, uint64_t to, const std::vector<size_t>& due,
                    const std::vector<SphereMove>& moves = {});

}  // namespace tp::sim
