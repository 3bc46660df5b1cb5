#pragma once
// Where a box can show in a frame: the pixels a pass that draws inside it
// may write, so that a pass over the frame can leave the rest as they were.
#include <glm/glm.hpp>

namespace tp::render {

// Pixels [x0, x1) x [y0, y1) of a frame.
struct PixelRect {
  glm::uvec2 lo{0u}, hi{0u};
  bool empty() const { return lo.x >= hi.x || lo.y >= hi.y; }
};

PixelRect united(const PixelRect& a, const PixelRect& b);

// The pixels whose centres the axis-aligned box [lo, hi] can cover, seen
// through `viewProjection` (Vulkan clip space, pixel p's centre at NDC
// (p + 0.5) / pixels * 2 - 1) in a frame of `pixels`, with a pixel's margin
// for rounding. Empty when the box lies wholly outside one of the view
// frustum's planes; else the whole frame when a corner is at or behind the
// camera's plane (the projection then need not be the corners' hull).
PixelRect pixelsCovering(const glm::mat4& viewProjection, glm::uvec2 pixels, glm::vec3 lo, glm::vec3 hi);

}  // namespace tp::render
