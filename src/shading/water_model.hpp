#pragma once
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"
#include "shared/ground.h"
#include "shared/water_surface.h"
#include "sim/water_scene.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

// Two triangles per grid quad, counter-clockwise seen from above. With
// `step` above 1, the coarser grid through every step-th row and column (and
// the last), over the same vertices: a mesh of fewer triangles for frames in
// which a quad is a fraction of a pixel (shading/grid_detail.hpp).
std::vector<uint32_t> waterGridIndices(uint32_t n, uint32_t step = 1);
// The same triangles, in the same order with the same corners first, as one
// triangle strip per row of quads, rows separated by kStripRestart: a third of
// the indices, so a third of the vertex shader invocations where the device
// shades each index (lavapipe: on one thread, the cost of a mesh pass that
// does not shrink with the frame).
inline constexpr uint32_t kStripRestart = 0xFFFFFFFFu;
std::vector<uint32_t> waterGridStrips(uint32_t n, uint32_t step = 1);
shader::WaterSurfaceParams waterSurfaceParams(const scene::Scene& scene);
// The ground's push constants, with the pool's hole when there is a pool.
shader::GroundParams groundParams(const scene::Scene& scene);

// Unit normals of the surface's vertices from central differences of u, one
// sided at the edges: the normals water_surface.vert computes.
std::vector<glm::vec3> waterVertexNormals(const sim::WaterState& water, float extent);

// The water surface reaching the walls, for the light through it (the
// caustics: caustics.vert draws the same mesh): (n + 2)^2 vertices, the
// inner n^2 the cells' centres, the outer ring on the walls with its edge
// cell's height and its normal without the slope across the wall (the
// walls reflect: lib/water_grid.glsl's wallGridPosition and wallGridNormal).
struct WaterToTheWalls {
  scene::Mesh mesh;
  std::vector<glm::vec3> normals;
};
WaterToTheWalls waterSurfaceToTheWalls(const scene::Scene& scene, const sim::WaterState& water);

// Whether the camera is over the water's square (and so may be under its
// surface); elsewhere the medium around it is air whatever the water does.
bool cameraOverWater(const scene::Scene& scene);

// Whether the water's rays refract by the apparent-depth guess
// (render.refraction "apparent"), which reads the frame drawn under the water.
bool apparentRefraction(const scene::Scene& scene);

// Whether the camera sees the pool's floor only through the water's surface,
// whose shader then shows it by its own rays: with accurate refraction, from
// a camera over the rim and away from the water's square, over water that
// keeps within `waveHeight` of its rest level (by its last statistics)
// between the floor's highest point and the rim, when no line from the
// camera is steep enough to see the floor through the slot between the
// water's mesh and a wall (the mesh spans the cells' centres, half a cell
// short of the walls).
bool floorSeenOnlyThroughWater(const scene::Scene& scene, float waveHeight, float floorTop);
// Where the floor is seen only through the water: a height in the pool below
// which the camera sees everything through the water too. Below the lowest
// water, a line from the camera meets a wall directly only through that
// wall's slot, which it crosses no steeper than it reaches it: it goes no
// lower than the lowest water less the slot's width times that slope. The
// height is twice that reach below the lowest water, so no such line meets
// it.
float seenOnlyThroughWaterBelow(const scene::Scene& scene, float waveHeight);

// The medium around the camera given the water's state (none: air), as
// camera_medium.comp decides it on the GPU.
shader::CameraMedium cameraMedium(const scene::Scene& scene, const sim::WaterState* water);
// Whether the scene's water scatters light (water.scattering above 0): its
// shaders then hold the scattering's code (the TP_SCATTERING variants).
bool hasWaterScattering(const scene::Scene& scene);
// The medium of a camera in the air: nothing between it and what it sees.
shader::CameraMedium cameraInAir();

// The triangles a frame shows, in world space: the ground around the pool's
// hole, the pool's walls and floor, the objects, and, given its state, the water
// surface.
std::vector<scene::Mesh> sceneMeshes(const scene::Scene& scene, const sim::WaterState* water, float time);

}  // namespace tp::render
