#pragma once
// Aerial perspective (haze.comp, shared/haze.h): the frame's colour faded
// towards the sky at the horizon with the distance its depth gives. Declared
// only for a scene with a haze distance (sky.haze_distance).
#include "render/surfaces.hpp"

namespace tp::render {

class Haze {
 public:
  explicit Haze(const gpu::Context& ctx);
  // Its pass over `frame`'s colour, reading its depth (made sampled).
  void declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in, float hazeDistance) const;

 private:
  gpu::Pipeline pipeline_;
};

}  // namespace tp::render
