#pragma once
// Morphological anti-aliasing of the tonemapped frame (antialias.comp): the
// viewer's cheap anti-aliasing, scene key render.antialiasing
// "morphological" (docs/rendering.md, "Anti-aliasing").
#include "render/surfaces.hpp"

namespace tp::render {

class MorphologicalAntialiasing {
 public:
  MorphologicalAntialiasing(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D extent);
  // The tonemapped frame it reads: the tonemap pass writes here instead of the LDR target.
  const GraphImage& input() const { return inputRef_; }
  // Its pass: input() filtered into `ldr` where `depth` (the frame's depth
  // target, sampled) has a silhouette.
  void declare(FrameGraph& graph, const GraphImage& ldr, const GraphImage& depth, vk::Sampler linearClamp,
               vk::Sampler nearest) const;

 private:
  gpu::Pipeline pipeline_;
  gpu::Image input_;
  GraphImage inputRef_;
};

}  // namespace tp::render
