#pragma once
#include <vector>

#include "render/renderer.hpp"

namespace tp::render {

// The opaque surfaces' G-buffer of a frame (RenderedFrame::gbufferDepth and
// gbufferNormal, read back with FrameRequest::ao) in world space, as the AOV
// images lay it out: RGBA per pixel, position +inf and normal zero where no
// surface was drawn. Positions are reconstructed from depth with the shaders'
// own viewPositionFromDepth (shared/ssao.h), so this is also how a test sees
// what SSAO sees.
struct WorldGbuffer {
  std::vector<float> position;
  std::vector<float> normal;
  // Per pixel, metres: how far the reconstructed position may lie from the
  // rasterised surface, from the depth buffer's own precision (a few float
  // steps of depth, which grow with the square of the distance).
  std::vector<float> uncertainty;
};
WorldGbuffer worldGbuffer(const RenderedFrame& frame);

}  // namespace tp::render
