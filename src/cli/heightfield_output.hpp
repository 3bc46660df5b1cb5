#pragma once
#include <cstdint>
#include <string>

#include "scene/scene.hpp"
#include "sim/water_state.hpp"

namespace tp::app {

// Whether `export --out` names a heightfield (.exr) rather than a mesh.
bool isHeightfieldOutput(const std::string& path);

// The water as a heightfield a DCC displaces a grid with: an EXR of n x n
// float pixels, pixel (i, j) (column i, row j from the top) the cell centred
// at x = -extent/2 + (i + 1/2) h, z = -extent/2 + (j + 1/2) h: the pool seen
// from above, as the exported meshes' UVs lay an image over it
// (shading/shaded_meshes); channel Y its world height (water.level + u),
// N.R N.G N.B its unit normal's x, y, z as the renderer shades it; with the
// frame number, the scene's frame rate and the software.
void writeHeightfield(const std::string& path, const scene::Scene& scene, const sim::WaterState& water, uint32_t frame);

}  // namespace tp::app
