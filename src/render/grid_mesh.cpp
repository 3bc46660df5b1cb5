#include "render/grid_mesh.hpp"

#include <stdexcept>

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "shading/water_model.hpp"

namespace tp::render {

GridMesh::GridMesh(const gpu::Context& ctx, uint32_t vertices, bool strips, const std::string& name)
    : vertices_(vertices) {
  for (uint32_t level = 0; level < kLevels; ++level) {
    const uint32_t step = 1u << level;
    const std::vector<uint32_t> indices = strips ? waterGridStrips(vertices, step) : waterGridIndices(vertices, step);
    indices_[level] = gpu::createFilledBuffer(ctx, indices, vk::BufferUsageFlagBits::eIndexBuffer,
                                              gpu::MemoryUse::Device, name + " indices, step " + std::to_string(step));
    counts_[level] = uint32_t(indices.size());
  }
}

bool GridMesh::setStep(uint32_t step) {
  for (uint32_t level = 0; level < kLevels; ++level) {
    if (step != 1u << level) continue;
    const bool changed = level != level_;
    level_ = level;
    return changed;
  }
  throw std::invalid_argument("a grid mesh's step is 1, 2 or 4, not " + std::to_string(step));
}

void GridMesh::draw(const vk::raii::CommandBuffer& cmd) const {
  cmd.bindIndexBuffer(indices_[level_].handle(), 0, vk::IndexType::eUint32);
  gpu::drawIndexed(cmd, counts_[level_]);
}

}  // namespace tp::render
