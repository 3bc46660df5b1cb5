#pragma once
// The sky: the procedural one, filled by a compute pass on the first frame
// (cached: its parameters are fixed), or an image, uploaded once (then no
// pass at all); and the background pass that shows it behind everything.
#include <optional>

#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shading/sky_model.hpp"
#include "shared/sky.h"

namespace tp::render {

class Sky {
 public:
  Sky(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene);
  GraphImage image() const { return ref_; }
  // What lights the scene: the sun and the sky's SH9.
  const SkyLight& light() const { return light_; }
  // The procedural sky's pass; nothing for a sky image.
  void declareSky(FrameGraph& graph) const;
  // The sky behind everything, seen through each pixel's view ray, drawn
  // after the opaque surfaces where their depth left the far plane: the
  // depth test before the shader leaves out the pixels they cover.
  void declareBackground(FrameGraph& graph, const SurfaceTargets& surfaces, const FrameInputs& in) const;

 private:
  gpu::Image image_;
  GraphImage ref_;
  SkyLight light_;
  shader::SkyParams params_{};
  std::optional<gpu::Pipeline> skyPipeline_;  // the procedural sky's
  gpu::Pipeline background_;
};

}  // namespace tp::render
