#include "render/ssao_passes.hpp"

#include "gpu/descriptors.hpp"
#include "render/ssao_model.hpp"

namespace tp::render {

SsaoPasses::SsaoPasses(const gpu::Context& ctx)
    : ssao(gpu::createComputePipeline(ctx, "ssao.comp", sizeof(shader::SsaoParams))),
      blur(gpu::createComputePipeline(ctx, "ao_blur.comp", sizeof(shader::AoBlurParams))),
      upsample(gpu::createComputePipeline(ctx, "ao_upsample.comp", sizeof(shader::AoUpsampleParams))),
      apply(gpu::createComputePipeline(ctx, "ao_apply.comp", sizeof(shader::AoApplyParams))) {}

void SsaoPasses::declare(FrameGraph& graph, const SurfaceTargets& surfaces, const AoImages& images,
                         const gpu::Buffer& frameUniforms, const gpu::Buffer& kernel, vk::Sampler depthSampler,
                         const scene::Ao& ao) const {
  const gpu::Image& depth = *surfaces.depth.image;
  const vk::Extent2D frame = depth.extent;
  const shader::SsaoParams params = ssaoParams(ao, frame.width, frame.height);
  graph.pass("ssao",
             {{surfaces.depth.ref, Use::ComputeSample}, {surfaces.normal.ref, Use::ComputeRead}, {images.raw.ref, Use::ComputeWrite}},
             [this, &depth, normal = surfaces.normal.image, raw = images.raw.image, &frameUniforms, &kernel, depthSampler,
              params](PassContext& pc) {
               gpu::bindPipeline(pc.cmd, ssao, params);
               gpu::DescriptorWrites()
                   .uniformBuffer(0, frameUniforms)
                   .sampledImage(1, depth, depthSampler)
                   .storageImage(2, *normal)
                   .uniformBuffer(3, kernel)
                   .storageImage(4, *raw)
                   .bind(pc.cmd, ssao, pc.descriptors);
               gpu::dispatchCovering(pc.cmd, ssao, params.size.x, params.size.y);
             });

  // Both directions of the blur, and the upsample, read the depth the same way.
  auto declareFilter = [&](const char* name, const gpu::Pipeline& pipeline, Target from, Target to, auto push,
                           uint32_t width, uint32_t height) {
    graph.pass(name, {{surfaces.depth.ref, Use::ComputeSample}, {from.ref, Use::ComputeRead}, {to.ref, Use::ComputeWrite}},
               [&pipeline, &depth, from = from.image, to = to.image, &frameUniforms, depthSampler, push, width,
                height](PassContext& pc) {
                 gpu::bindPipeline(pc.cmd, pipeline, push);
                 gpu::DescriptorWrites()
                     .uniformBuffer(0, frameUniforms)
                     .sampledImage(1, depth, depthSampler)
                     .storageImage(2, *from)
                     .storageImage(3, *to)
                     .bind(pc.cmd, pipeline, pc.descriptors);
                 gpu::dispatchCovering(pc.cmd, pipeline, width, height);
               });
  };
  const uint32_t w = params.size.x, h = params.size.y;
  if (images.blurred.image) {
    declareFilter("ao blur x", blur, images.raw, images.blurX, aoBlurParams(ao, 0, frame.width, frame.height), w, h);
    declareFilter("ao blur y", blur, images.blurX, images.blurred, aoBlurParams(ao, 1, frame.width, frame.height), w, h);
  }
  if (images.full.image) {
    declareFilter("ao upsample", upsample, images.lowResult(), images.full,
                  aoUpsampleParams(ao, frame.width, frame.height), frame.width, frame.height);
  }

  const shader::AoApplyParams applyParams{glm::uvec4(frame.width, frame.height, 0u, 0u)};
  const Target result = images.result();
  graph.pass("ao apply",
             {{surfaces.color.ref, Use::ComputeReadWrite}, {surfaces.ambient.ref, Use::ComputeRead}, {result.ref, Use::ComputeRead}},
             [this, color = surfaces.color.image, ambient = surfaces.ambient.image, ao = result.image,
              applyParams](PassContext& pc) {
               gpu::bindPipeline(pc.cmd, apply, applyParams);
               gpu::DescriptorWrites()
                   .storageImage(0, *color)
                   .storageImage(1, *ambient)
                   .storageImage(2, *ao)
                   .bind(pc.cmd, apply, pc.descriptors);
               gpu::dispatchCovering(pc.cmd, apply, applyParams.size.x, applyParams.size.y);
             });
}

}  // namespace tp::render
