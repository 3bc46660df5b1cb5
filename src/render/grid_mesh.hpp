#pragma once
// A square grid mesh over the pool (the water's, the floor's) at each step
// shading/grid_detail.hpp allows: the index buffers, made once, and the step
// frames draw it at now. The vertices are the full grid's at every step.
#include <array>
#include <cstdint>
#include <string>

#include "gpu/context.hpp"
#include "gpu/memory.hpp"
#include "shading/grid_detail.hpp"

namespace tp::render {

class GridMesh {
 public:
  // `strips`: triangle strips (waterGridStrips), else a triangle list
  // (waterGridIndices).
  GridMesh(const gpu::Context& ctx, uint32_t vertices, bool strips, const std::string& name);
  uint32_t vertices() const { return vertices_; }
  // Returns whether it changed. `step`: 1, 2 or 4.
  bool setStep(uint32_t step);
  uint32_t step() const { return 1u << level_; }
  // Binds the step's indices and draws them; the pipeline is bound.
  void draw(const vk::raii::CommandBuffer& cmd) const;

 private:
  static constexpr size_t kLevels = 3;  // steps 1, 2 and 4
  static_assert(1u << (kLevels - 1) == kMaxGridStep);
  uint32_t vertices_;
  std::array<gpu::Buffer, kLevels> indices_;
  std::array<uint32_t, kLevels> counts_{};
  uint32_t level_ = 0;
};

}  // namespace tp::render
