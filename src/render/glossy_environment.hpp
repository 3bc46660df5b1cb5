#pragma once
// What the glossy surfaces reflect: the sky prefiltered by a cached pass (on
// the first frame, and again only if the sky changes); without glossy
// surfaces no pass, and one black texel for the shaders to bind.
#include <optional>

#include "render/glossy_prefilter.hpp"
#include "scene/scene.hpp"

namespace tp::render {

class GlossyEnvironment {
 public:
  GlossyEnvironment(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, const gpu::Image& sky);
  GraphImage image() const { return ref_; }
  void declare(FrameGraph& graph, const GraphImage& sky, vk::Sampler sampler);

 private:
  std::optional<GlossyPrefilter> prefilter_;
  gpu::Image none_;
  GraphImage ref_;
};

}  // namespace tp::render
