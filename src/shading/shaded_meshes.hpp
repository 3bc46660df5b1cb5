#pragma once
#include <vector>

#include "scene/scene.hpp"
#include "scene/shaded_mesh.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

// The meshes `tidepool export` writes: sceneMeshes' triangles, in its order
// and with its names, each with the normals the renderer shades it with,
// texture coordinates and its material. Two differ from sceneMeshes for a
// DCC's sake: each box face has its own corners (flat normals, as box.vert
// draws it), and the water reaches the walls (waterSurfaceToTheWalls: a ring
// of vertices on them holding the outermost cells' heights), so it meets the
// walls without a crack. The reference tracer's camera rays keep
// sceneMeshes' water, whose vertices are the cells.
std::vector<scene::ShadedMesh> shadedSceneMeshes(const scene::Scene& scene, const sim::WaterState* water, float time);

// The water surface as exported: waterSurfaceToTheWalls' mesh, (n + 2)^2
// vertices, the cells' centres and the ring on the walls (x, z = +-extent/2),
// two triangles a quad.
scene::ShadedMesh exportedWaterMesh(const scene::Scene& scene, const sim::WaterState& water);

}  // namespace tp::render
