#include "render/sky.hpp"

#include "gpu/barriers.hpp"
#include "gpu/commands.hpp"
#include "gpu/submit.hpp"
#include "render/pass_kinds.hpp"
#include "render/sky_image.hpp"
#include "shading/frame_uniforms.hpp"

namespace tp::render {

Sky::Sky(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, bool gbuffer)
    : mips_(ctx),
      // At the far plane, tested against the surfaces' depth and not writing it.
      background_(gpu::createGraphicsPipeline(
          ctx,
          {.vertexShader = "fullscreen.vert",
           .fragmentShader = gbuffer ? "sky_background.frag" : "sky_background.color_only.frag",
           .colorFormats = gbuffer ? std::vector{kHdrFormat, kGbufferFormat, kGbufferFormat} : std::vector{kHdrFormat},
           .depthFormat = kDepthFormat,
           .depthTest = true})) {
  if (!scene.sky.image.empty()) {
    const SkyImage image = loadSkyImage(scene.sky);
    image_ = uploadSkyImage(ctx, image, "sky image texture", skyMipLevels({image.width, image.height}));
    fillMips(ctx);
    ref_ = graph.image("sky", image_, vk::ImageLayout::eShaderReadOnlyOptimal);
    cpuImage_ = image;
    light_ = sceneLight(scene, [this](glm::vec3 d) { return radiance(d); });
    return;
  }
  const vk::Extent2D extent{scene.sky.textureWidth, scene.sky.textureWidth / 2};
  image_ =
      gpu::createImage2D(ctx, extent, kSkyFormat, vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled,
                         "sky texture", skyMipLevels(extent));
  ref_ = graph.image("sky", image_);
  params_ = skyParams(scene.sky);
  light_ = sceneLight(scene, [this](glm::vec3 d) { return radiance(d); });
  skyPipeline_ = gpu::createComputePipeline(ctx, "sky.comp", sizeof(shader::SkyParams));
}

glm::vec3 Sky::radiance(glm::vec3 d) const { return skyRadianceWithout(params_, cpuImage_ ? &*cpuImage_ : nullptr, d); }

void Sky::fillMips(const gpu::Context& ctx) {
  gpu::DescriptorArena descriptors(ctx);
  gpu::submitAndWait(
      ctx,
      [&](const vk::raii::CommandBuffer& cmd) {
        // Chained to the upload's barrier, whose second scope was the fragment stage.
        auto toGeneral = gpu::imageBarrier(
            image_.handle(), image_.aspect, {vk::PipelineStageFlagBits2::eFragmentShader, vk::AccessFlagBits2::eNone},
            vk::ImageLayout::eShaderReadOnlyOptimal,
            {vk::PipelineStageFlagBits2::eComputeShader,
             vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eShaderStorageWrite},
            vk::ImageLayout::eGeneral);
        gpu::pipelineBarrier(cmd, {}, std::span(&toGeneral, 1));
        mips_.record(cmd, descriptors, image_);
        // Later submissions come later in submission order: this covers their reads.
        auto toShader =
            gpu::imageBarrier(image_.handle(), image_.aspect, gpu::access::computeWrite, vk::ImageLayout::eGeneral,
                              {vk::PipelineStageFlagBits2::eFragmentShader | vk::PipelineStageFlagBits2::eComputeShader,
                               vk::AccessFlagBits2::eShaderSampledRead},
                              vk::ImageLayout::eShaderReadOnlyOptimal);
        gpu::pipelineBarrier(cmd, {}, std::span(&toShader, 1));
      },
      "sky image mips");
}

void Sky::declareSky(FrameGraph& graph) const {
  if (!skyPipeline_) return;
  // The pass binds its own sets: level 0, then level by level (SkyMips).
  graph.pass(passes::kSky,
             [this](PassBuilder& pass) {
               const gpu::Image& sky = pass.attach(ref_, Use::ComputeWrite);
               return [this, &sky](PassContext& pc) {
                 gpu::bindPipeline(pc.cmd, *skyPipeline_, params_);
                 gpu::DescriptorWrites().storageImageLevel(0, sky, 0).bind(pc.cmd, *skyPipeline_, pc.descriptors);
                 gpu::dispatchCovering(pc.cmd, *skyPipeline_, params_.counts.x, params_.counts.x / 2);
                 mips_.record(pc.cmd, pc.descriptors, sky);
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
