#pragma once
// Linear HDR to the 8-bit sRGB preview (exposure, ACES filmic fit, sRGB).
#include "render/surfaces.hpp"

namespace tp::render {

class Tonemap {
 public:
  explicit Tonemap(const gpu::Context& ctx);
  void declare(FrameGraph& graph, const GraphImage& hdr, const GraphImage& ldr, float exposure) const;

 private:
  gpu::Pipeline pipeline_;
};

}  // namespace tp::render
