#pragma once
// What a pass needs to draw the water grid: the state buffers (read in the
// vertex stage; the current one chosen when the pass records), the grid's
// mesh at the frame's step and the surface's push constants.
#include "graph/pass_builder.hpp"
#include "render/grid_mesh.hpp"
#include "shared/water_surface.h"

namespace tp::render {

struct WaterDraw {
  SwappingBuffer state;
  const GridMesh* mesh = nullptr;
  shader::WaterSurfaceParams params{};
};

// The grid as triangle strips (waterGridStrips); the pipeline is bound.
inline void drawWater(const vk::raii::CommandBuffer& cmd, const WaterDraw& water) { water.mesh->draw(cmd); }

}  // namespace tp::render
