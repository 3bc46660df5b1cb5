#pragma once
#include <vector>

#include "gpu/vulkan.hpp"
#include "scene/mesh.hpp"
#include "sim/gpu_stepper.hpp"
#include "scene/scene.hpp"
#include "shared/ground.h"
#include "shared/water_surface.h"
#include "sim/water_params.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

// Records `count` steps of the scene's water from scene time `start`
// (seconds): each step of dt, preceded, for every sphere with a path, by its
// displacement of the water from where it was at the step's start to where
// it is at its end.
void recordWaterSteps(const vk::raii::CommandBuffer& cmd, sim::GpuStepper& water, const scene::Scene& scene,
                      double start, uint64_t count);

// The scene's water after `frame` frames, simulated on the GPU exactly as the
// renderer does it (its later drops each on its frame), downloaded (for
// export and the CPU reference).
sim::WaterState simulateWater(const gpu::Context& ctx, const scene::Scene& scene, uint32_t frame);

// From the scene's water to the simulation and the surface pass: the one place
// where the square centred on the origin meets the grid's cell coordinates.
sim::WaterParams waterParams(const scene::Water& water);

// `water` with the dynamics of `from`: its wave speed, damping, boundary and
// max slope, what a live renderer changes (Renderer::setWaterDynamics).
scene::Water withDynamicsOf(scene::Water water, const scene::Water& from);
// Whether two waters move alike, being equal but for their ior and
// absorption (which only shade): a renderer can carry one's state on to the other.
bool sameWaterMotion(const scene::Water& a, const scene::Water& b);
// World position to the simulation's frame, whose grid starts at the water square's corner.
glm::vec3 worldToGrid(const scene::Water& water, glm::vec3 p);
// Seconds per simulation step: the frame time split into the fewest stable substeps.
uint32_t waterSubsteps(const scene::Water& water);
double waterStep(const scene::Water& water);
// Flat water with the scene's frame-0 drops, at rest (sim::startAtRest).
sim::WaterState waterInitialState(const scene::Water& water);
// Two triangles per grid quad, counter-clockwise seen from above.
std::vector<uint32_t> waterGridIndices(uint32_t n);
// The same triangles, in the same order with the same corners first, as one
// triangle strip per row of quads, rows separated by kStripRestart: a third of
// the indices, so a third of the vertex shader invocations where the device
// shades each index (lavapipe: on one thread, the cost of a mesh pass that
// does not shrink with the frame).
inline constexpr uint32_t kStripRestart = 0xFFFFFFFFu;
std::vector<uint32_t> waterGridStrips(uint32_t n);
shader::WaterSurfaceParams waterSurfaceParams(const scene::Scene& scene);
// The ground's push constants, with the pool's hole when there is a pool.
shader::GroundParams groundParams(const scene::Scene& scene);

// Unit normals of the surface's vertices from central differences of u, one
// sided at the edges: the normals water_surface.vert computes.
std::vector<glm::vec3> waterVertexNormals(const sim::WaterState& water, float extent);

// Whether the camera is over the water's square (and so may be under its
// surface); elsewhere the medium around it is air whatever the water does.
bool cameraOverWater(const scene::Scene& scene);

// The medium around the camera given the water's state (none: air), as
// camera_medium.comp decides it on the GPU.
shader::CameraMedium cameraMedium(const scene::Scene& scene, const sim::WaterState* water);

// The triangles a frame shows, in world space: the ground around the pool's
// hole, the pool's walls and floor, the objects, and, given its state, the water
// surface.
std::vector<scene::Mesh> sceneMeshes(const scene::Scene& scene, const sim::WaterState* water, float time);

}  // namespace tp::render
