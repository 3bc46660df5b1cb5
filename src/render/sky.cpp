#include "render/sky.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "render/sky_image.hpp"

namespace tp::render {

Sky::Sky(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, bool gbuffer)
    // At the far plane, tested against the surfaces' depth and not writing it.
    : background_(gpu::createGraphicsPipeline(
          ctx,
          {.vertexShader = "fullscreen.vert",
           .fragmentShader = gbuffer ? "sky_background.frag" : "sky_background.color_only.frag",
           .colorFormats = gbuffer ? std::vector{kHdrFormat, kGbufferFormat, kGbufferFormat} : std::vector{kHdrFormat},
           .depthFormat = kDepthFormat,
           .depthTest = true})) {
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

std::function<void(PassContext&)> Sky::background(PassBuilder& pass, const FrameInputs& in) const {
  Bindings& set = pass.bindings()
                      .uniformBuffer(0, in.uniforms, Use::HostData)
                      .sampledImage(1, in.sky, in.equirect, Use::FragmentSample);
  return [this, &set](PassContext& pc) {
    pc.cmd.bindPipeline(background_.bindPoint, *background_.pipeline);
    set.bind(pc.cmd, background_, pc.descriptors);
    gpu::draw(pc.cmd, 3);
  };
}

}  // namespace tp::render
