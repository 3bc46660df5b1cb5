#pragma once
// What a pass needs to draw the water grid: the state buffers (read in the
// vertex stage; the current one chosen when the pass records), the grid's
// indices and the surface's push constants.
#include "gpu/commands.hpp"
#include "graph/pass_builder.hpp"
#include "shared/water_surface.h"

namespace tp::render {

struct WaterDraw {
  SwappingBuffer state;
  const gpu::Buffer* indices = nullptr;
  uint32_t indexCount = 0;
  shader::WaterSurfaceParams params{};
};

// The grid as triangle strips (waterGridStrips); the pipeline is bound.
inline void drawWater(const vk::raii::CommandBuffer& cmd, const WaterDraw& water) {
  cmd.bindIndexBuffer(water.indices->handle(), 0, vk::IndexType::eUint32);
  gpu::drawIndexed(cmd, water.indexCount);
}

}  // namespace tp::render
