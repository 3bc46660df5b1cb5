#pragma once
// The medium around the camera: air (zeros, uploaded first) while the camera
// is away from the water's square, where it cannot be under the surface;
// decided on the GPU after the simulation (camera_medium.comp, one
// invocation) while it is over it, and once more when it leaves, to write
// air again. Read by the passes that draw what the camera sees directly.
#include <functional>
#include <optional>

#include "render/surfaces.hpp"
#include "render/water_draw.hpp"

namespace tp::render {

class CameraMedium {
 public:
  CameraMedium(const gpu::Context& ctx, FrameGraph& graph, bool water);
  GraphBuffer buffer() const { return ref_; }
  // Cached: recorded again only when the water or the frame uniforms (the
  // camera) changed, and only while `runIf` says the medium may differ from
  // what the buffer holds.
  void declare(FrameGraph& graph, const WaterDraw& water, const FrameInputs& in, std::function<bool()> runIf) const;

 private:
  gpu::Buffer medium_;
  GraphBuffer ref_;
  std::optional<gpu::Pipeline> pipeline_;  // with water only
};

}  // namespace tp::render
