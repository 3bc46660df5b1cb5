#include "render/sky.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "render/sky_image.hpp"

namespace tp::render {

Sky::Sky(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene)
    : background_(gpu::createGraphicsPipeline(
          ctx,
          {.vertexShader = "fullscreen.vert", .fragmentShader = "sky_background.frag", .colorFormats = {kHdrFormat}})) {
  if (!scene.sky.image.empty()) {
    const SkyImage image = loadSkyImage(scene.sky);
    image_ = uploadSkyImage(ctx, image);
    light_ = skyImageLight(image);
    ref_ = graph.image("sky", image_, vk::ImageLayout::eShaderReadOnlyOptimal);
    return;
  }
  image_ = gpu::createImage2D(ctx, {scene.sky.textureWidth, scene.sky.textureWidth / 2}, kSkyFormat,
                              vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled, "sky texture");
  light_ = proceduralSkyLight(scene.sky);
  ref_ = graph.image("sky", image_);
  params_ = skyParams(scene.sky);
  skyPipeline_ = gpu::createComputePipeline(ctx, "sky.comp", sizeof(shader::SkyParams));
}

void Sky::declareSky(FrameGraph& graph) const {
  if (!skyPipeline_) return;
  graph.pass(passes::kSky,
             [this](PassBuilder& pass) {
               Bindings& set = pass.bindings().storageImage(0, ref_, Use::ComputeWrite);
               return [this, &set](PassContext& pc) {
                 gpu::bindPipeline(pc.cmd, *skyPipeline_, params_);
                 set.bind(pc.cmd, *skyPipeline_, pc.descriptors);
                 gpu::dispatchCovering(pc.cmd, *skyPipeline_, params_.counts.x, params_.counts.x / 2);
               };
             },
             {.cached = true, .runIf = {}});
}

void Sky::declareBackground(FrameGraph& graph, const GraphImage& color, const FrameInputs& in) const {
  graph.pass(passes::kBackground, [this, color, in](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .uniformBuffer(0, in.uniforms, Use::HostData)
                        .sampledImage(1, in.sky, in.equirect, Use::FragmentSample);
    const gpu::Image& target = pass.attach(color, Use::ColorWrite);
    return [this, &set, &target](PassContext& pc) {
      auto info = attachment(target, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eDontCare);
      renderTo(pc.cmd, std::span(&info, 1), nullptr, target.extent, [&] {
        pc.cmd.bindPipeline(background_.bindPoint, *background_.pipeline);
        set.bind(pc.cmd, background_, pc.descriptors);
        gpu::draw(pc.cmd, 3);
      });
    };
  });
}

}  // namespace tp::render
