#include "render/glossy_environment.hpp"

#include "render/sky_image.hpp"
#include "shading/glossy_model.hpp"

namespace tp::render {

GlossyEnvironment::GlossyEnvironment(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene,
                                     const gpu::Image& sky) {
  if (hasGlossySurface(scene)) {
    prefilter_.emplace(ctx, sky.extent.width, sky.extent.height);
    ref_ = graph.image("glossy environment", prefilter_->map());
  } else {
    none_ = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(0.0f)}}, "no glossy environment");
    ref_ = graph.image("glossy environment", none_, vk::ImageLayout::eShaderReadOnlyOptimal);
  }
}

void GlossyEnvironment::declare(FrameGraph& graph, const GraphImage& sky, vk::Sampler sampler) {
  if (prefilter_) prefilter_->declare(graph, sky, sampler, ref_);
}

}  // namespace tp::render
