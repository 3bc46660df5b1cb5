#include "render/ambient_occlusion.hpp"

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "render/pass_kinds.hpp"
#include "shading/ssao_model.hpp"

namespace tp::render {
namespace {

vk::DeviceSize pixels(vk::Extent2D e) { return vk::DeviceSize(e.width) * e.height; }

}  // namespace

AmbientOcclusion::AmbientOcclusion(const gpu::Context& ctx, FrameGraph& graph, const scene::Ao& ao, vk::Extent2D frame,
                                   bool applyLater)
    : ao_(ao),
      frame_(frame),
      low_(aoExtent(ao, frame.width, frame.height)),
      ssao_(gpu::createComputePipeline(ctx, "ssao.comp", sizeof(shader::SsaoParams))),
      blur_(gpu::createComputePipeline(ctx, "ao_blur.comp", sizeof(shader::AoBlurParams))),
      upsample_(gpu::createComputePipeline(ctx, "ao_upsample.comp", sizeof(shader::AoUpsampleParams))),
      aoReadback_(ctx, graph, "AO readback", pixels(frame) * 4),
      rawReadback_(ctx, graph, "raw AO readback", pixels(low_) * 4),
      depthReadback_(ctx, graph, "G-buffer depth readback", pixels(frame) * 4),
      normalReadback_(ctx, graph, "G-buffer normal readback", pixels(frame) * 8) {
  const auto usage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
  auto makeImage = [&](gpu::Image& image, vk::Extent2D extent, const char* name) {
    image = gpu::createImage2D(ctx, extent, kAoFormat, usage, name);
    return graph.image(name, image);
  };
  raw_ = makeImage(rawImage_, low_, "AO raw");
  viewDepth_ = makeImage(viewDepthImage_, low_, "AO view depth");
  if (ao.blur != "off") {
    blurX_ = makeImage(blurXImage_, low_, "AO blurred in x");
    blurred_ = makeImage(blurredImage_, low_, "AO blurred");
  }
  if (low_ != frame) full_ = makeImage(fullImage_, frame, "AO upsampled");
  // At half resolution the apply pass upsamples as it applies.
  if (!applyLater) {
    apply_ = low_ != frame ? gpu::createComputePipeline(ctx, "ao_apply.upsample.comp", sizeof(shader::AoUpsampleParams))
                           : gpu::createComputePipeline(ctx, "ao_apply.comp", sizeof(shader::AoApplyParams));
  }
  const shader::SsaoKernel kernel = ssaoKernel(ao);
  kernel_ = gpu::createFilledBuffer(ctx, &kernel, sizeof(kernel), vk::BufferUsageFlagBits::eUniformBuffer,
                                    gpu::MemoryUse::Upload, "SSAO kernel");
}

std::optional<AoForResolve> AmbientOcclusion::forResolve(const SurfaceTargets& surfaces) const {
  if (apply_) return std::nullopt;  // its own pass applies it
  return AoForResolve{surfaces.ambient, lowResult(), viewDepth_, bool(full_),
                      aoUpsampleParams(ao_, frame_.width, frame_.height)};
}

void AmbientOcclusion::declare(FrameGraph& graph, const SurfaceTargets& surfaces, const FrameInputs& in,
                               const std::function<bool()>& surfacesChanged) const {
  const shader::SsaoParams params = ssaoParams(ao_, frame_.width, frame_.height);
  const PassOptions fromSurfaces{.cached = false, .runIf = surfacesChanged};
  graph.pass(
      passes::kSsao,
      [&, surfaces, in, params](PassBuilder& pass) {
        Bindings& set = pass.bindings()
                            .uniformBuffer(0, in.uniforms, Use::HostData)
                            .sampledImage(1, surfaces.depth, in.nearest, Use::ComputeSample)
                            .storageImage(2, surfaces.normal, Use::ComputeRead)
                            .constantBuffer(3, kernel_)
                            .storageImage(4, raw_, Use::ComputeWrite)
                            .storageImage(5, viewDepth_, Use::ComputeWrite);
        return [this, &set, params](PassContext& pc) {
          gpu::bindPipeline(pc.cmd, ssao_, params);
          set.bind(pc.cmd, ssao_, pc.descriptors);
          gpu::dispatchCovering(pc.cmd, ssao_, params.size.x, params.size.y);
        };
      },
      fromSurfaces);
  const vk::Extent2D size{params.size.x, params.size.y};
  if (blurred_) {
    for (const uint32_t direction : {0u, 1u}) {
      const shader::AoBlurParams push = aoBlurParams(ao_, direction, frame_.width, frame_.height);
      declareFilter(
          graph, direction == 0 ? passes::kAoBlurX : passes::kAoBlurY, blur_, surfaces, in,
          direction == 0 ? raw_ : blurX_, direction == 0 ? blurX_ : blurred_,
          [this, push](const vk::raii::CommandBuffer& cmd) { gpu::bindPipeline(cmd, blur_, push); }, size, false,
          fromSurfaces);
    }
  }
  // The upsampled AO as an image, for its readback alone: the graph leaves
  // the pass out of frames that do not ask for it.
  const shader::AoUpsampleParams upsampleParams = aoUpsampleParams(ao_, frame_.width, frame_.height);
  if (full_) {
    declareFilter(
        graph, passes::kAoUpsample, upsample_, surfaces, in, lowResult(), full_,
        [this, upsampleParams](const vk::raii::CommandBuffer& cmd) {
          gpu::bindPipeline(cmd, upsample_, upsampleParams);
        },
        frame_, true);
  }
  if (apply_) declareApply(graph, surfaces, in);
  declareReadback(graph, passes::kReadbackAo, result(), aoReadback_);
  declareReadback(graph, passes::kReadbackAoRaw, raw_, rawReadback_);
  declareReadback(graph, passes::kReadbackDepth, surfaces.depth, depthReadback_);
  declareReadback(graph, passes::kReadbackViewNormal, surfaces.normal, normalReadback_);
}

void AmbientOcclusion::declareApply(FrameGraph& graph, const SurfaceTargets& surfaces, const FrameInputs& in) const {
  const shader::AoUpsampleParams upsampleParams = aoUpsampleParams(ao_, frame_.width, frame_.height);
  const shader::AoApplyParams applyParams{glm::uvec4(frame_.width, frame_.height, 0u, 0u)};
  graph.pass(passes::kAoApply, [this, surfaces, in, applyParams, upsampleParams](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .storageImage(0, surfaces.color, Use::ComputeReadWrite)
                        .storageImage(1, surfaces.ambient, Use::ComputeRead)
                        .storageImage(2, lowResult(), Use::ComputeRead);
    if (full_) {
      set.uniformBuffer(3, in.uniforms, Use::HostData)
          .sampledImage(4, surfaces.depth, in.nearest, Use::ComputeSample)
          .storageImage(5, viewDepth_, Use::ComputeRead);
    }
    return [this, &set, applyParams, upsampleParams](PassContext& pc) {
      if (full_) {
        gpu::bindPipeline(pc.cmd, *apply_, upsampleParams);
      } else {
        gpu::bindPipeline(pc.cmd, *apply_, applyParams);
      }
      set.bind(pc.cmd, *apply_, pc.descriptors);
      gpu::dispatchCovering(pc.cmd, *apply_, frame_.width, frame_.height);
    };
  });
}

// Both directions of the blur, and the upsample, read the AO pixels' depths
// the SSAO pass stored; the upsample also reads the frame's depth.
void AmbientOcclusion::declareFilter(FrameGraph& graph, const PassKind& kind, const gpu::Pipeline& pipeline,
                                     const SurfaceTargets& surfaces, const FrameInputs& in, const GraphImage& from,
                                     const GraphImage& to,
                                     const std::function<void(const vk::raii::CommandBuffer&)>& push, vk::Extent2D size,
                                     bool frameDepth, PassOptions options) const {
  graph.pass(
      kind,
      [this, &pipeline, surfaces, in, from, to, push, size, frameDepth](PassBuilder& pass) {
        Bindings& set = pass.bindings().uniformBuffer(0, in.uniforms, Use::HostData);
        if (frameDepth) {
          set.sampledImage(1, surfaces.depth, in.nearest, Use::ComputeSample)
              .storageImage(4, viewDepth_, Use::ComputeRead);
        } else {
          set.storageImage(1, viewDepth_, Use::ComputeRead);
        }
        set.storageImage(2, from, Use::ComputeRead).storageImage(3, to, Use::ComputeWrite);
        return [&pipeline, &set, push, size](PassContext& pc) {
          push(pc.cmd);
          set.bind(pc.cmd, pipeline, pc.descriptors);
          gpu::dispatchCovering(pc.cmd, pipeline, size.width, size.height);
        };
      },
      std::move(options));
}

std::vector<ResourceRef> AmbientOcclusion::readbackRefs() const {
  return {aoReadback_.ref.ref, rawReadback_.ref.ref, depthReadback_.ref.ref, normalReadback_.ref.ref};
}

AmbientOcclusion::Readings AmbientOcclusion::read() const {
  return {readFloats(aoReadback_.buffer, pixels(frame_)), readFloats(rawReadback_.buffer, pixels(low_)),
          readFloats(depthReadback_.buffer, pixels(frame_)), readHalves(normalReadback_.buffer, pixels(frame_) * 4)};
}

}  // namespace tp::render
