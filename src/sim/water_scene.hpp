#pragma once
// The scene's water as the simulation sees it: its parameters, time step,
// initial state and the moving spheres' forcing, in the grid's frame.
#include <functional>
#include <vector>

#include "gpu/vulkan.hpp"
#include "scene/scene.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/water_params.hpp"
#include "sim/water_state.hpp"

namespace tp::sim {

// Records `count` steps of the scene's water from scene time `start`
// (seconds): each step of dt, preceded, for every sphere with a path, by its
// displacement of the water from where it was at the step's start to where
// it is at its end.
void recordWaterSteps(const vk::raii::CommandBuffer& cmd, GpuStepper& water, const scene::Scene& scene, double start,
                      uint64_t count);

// The scene's water after `frame` frames, simulated on the GPU exactly as the
// renderer does it (its later drops each on its frame), downloaded (for
// export and the CPU reference).
WaterState simulateWater(const gpu::Context& ctx, const scene::Scene& scene, uint32_t frame);
// The same for each frame from `first` to `last` in turn, in one run from the
// start: each frame's state is handed to `atFrame` as it is reached, so a
// sequence costs the steps to its last frame once. `atFrame` returns whether
// to go on: false ends the run there (a sequence stopped by a signal).
void simulateWaterFrames(const gpu::Context& ctx, const scene::Scene& scene, uint32_t first, uint32_t last,
                         const std::function<bool(uint32_t frame, const WaterState& water)>& atFrame);

// From the scene's water to the simulation and the surface pass: the one place
// where the square centred on the origin meets the grid's cell coordinates.
WaterParams waterParams(const scene::Water& water);
// The cells under the boxes that stand through the water's rest level: the
// water cannot enter them (WaterParams::solid). A cell is solid where its
// centre lies inside the box's footprint. Empty where no box crosses the level.
// Spheres are not solid: a moving one displaces the water instead, and the
// viewer can move any of them.
std::vector<uint32_t> solidCellsOf(const scene::Scene& scene);
// The same with the pool's rim (the ground's height over the rest level),
// over which the water along the walls spills, and the solid cells: what the
// renderer steps.
WaterParams waterParams(const scene::Scene& scene);

// `water` with the dynamics of `from`: its wave speed, damping, grid damping, boundary, max
// slope and sphere forcing, what a live renderer changes (Renderer::setWaterDynamics).
scene::Water withDynamicsOf(scene::Water water, const scene::Water& from);
// Whether two waters move alike, being equal but for their ior,
// absorption and scattering (which only shade): a renderer can carry one's state on to the other.
bool sameWaterMotion(const scene::Water& a, const scene::Water& b);
// World position to the simulation's frame, whose grid starts at the water square's corner.
glm::vec3 worldToGrid(const scene::Water& water, glm::vec3 p);
// Seconds per simulation step: the frame time split into the fewest stable substeps.
uint32_t waterSubsteps(const scene::Water& water);
double waterStep(const scene::Water& water);
// Flat water with the scene's frame-0 drops, at rest (startAtRest).
WaterState waterInitialState(const scene::Water& water);
}  // namespace tp::sim
