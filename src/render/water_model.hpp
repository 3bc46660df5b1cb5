#pragma once
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"
#include "shared/ground.h"
#include "shared/water_surface.h"
#include "sim/water_params.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

// From the scene's water to the simulation and the surface pass: the one place
// where the square centred on the origin meets the grid's cell coordinates.
sim::WaterParams waterParams(const scene::Water& water);
// Seconds per simulation step: the frame time split into the fewest stable substeps.
uint32_t waterSubsteps(const scene::Water& water);
double waterStep(const scene::Water& water);
// Flat water with the scene's drops, at rest (sim::startAtRest).
sim::WaterState waterInitialState(const scene::Water& water);
// Two triangles per grid quad, counter-clockwise seen from above.
std::vector<uint32_t> waterGridIndices(uint32_t n);
shader::WaterSurfaceParams waterSurfaceParams(const scene::Scene& scene);
// The ground's push constants, with the pool's hole when there is a pool.
shader::GroundParams groundParams(const scene::Scene& scene);

// The triangles a frame shows, in world space: the ground around the pool's
// hole, the pool's walls and floor, and, given its state, the water surface.
std::vector<scene::Mesh> sceneMeshes(const scene::Scene& scene, const sim::WaterState* water);

}  // namespace tp::render
