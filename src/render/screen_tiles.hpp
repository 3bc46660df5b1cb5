#pragma once
// The frame's square tiles (shared/screen_tiles.h), as the host counts them.
#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/context.hpp"
#include "shading/screen_rect.hpp"
#include "shared/screen_tiles.h"

namespace tp::render {

struct ScreenTiles {
  explicit ScreenTiles(vk::Extent2D frame)
      : perRow((frame.width + TP_SCREEN_TILE - 1) / TP_SCREEN_TILE),
        rows((frame.height + TP_SCREEN_TILE - 1) / TP_SCREEN_TILE),
        count(perRow * rows) {}
  // The tiles holding a pixel of `r`: x0, y0 to x1, y1, the ends left out.
  glm::uvec4 covering(const PixelRect& r) const {
    if (r.empty()) return glm::uvec4(0u);
    return {r.lo / uint32_t(TP_SCREEN_TILE), (r.hi + uint32_t(TP_SCREEN_TILE - 1)) / uint32_t(TP_SCREEN_TILE)};
  }
  glm::uvec4 all() const { return {0u, 0u, perRow, rows}; }

  uint32_t perRow, rows, count;
};

}  // namespace tp::render
