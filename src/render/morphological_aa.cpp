#include "render/morphological_aa.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shared/antialias.h"

namespace tp::render {
namespace {

// The thresholds of FXAA's "quality" defaults (Lottes 2011): an edge needs a
// luma range of 1/32, or 1/8 of the brightest corner; blends reach at most 8
// pixels each way. Lower thresholds blur texture detail, higher ones leave
// the fainter stair steps.
constexpr shader::MorphologicalParams kParams{.size = {0, 0},
                                              .contrastThreshold = 1.0f / 32.0f,
                                              .relativeThreshold = 1.0f / 8.0f,
                                              .spanMax = 8.0f,
                                              .reduceShare = 1.0f / 8.0f,
                                              .reduceMin = 1.0f / 128.0f,
                                              // A jump of the depth gives a share near 1; a plane's float
                                              // rounding, far less.
                                              .silhouetteShare = 0.5f};

}  // namespace

MorphologicalAntialiasing::MorphologicalAntialiasing(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D extent)
    : pipeline_(gpu::createComputePipeline(ctx, "antialias.comp", sizeof(shader::MorphologicalParams))),
      input_(gpu::createImage2D(ctx, extent, kLdrFormat,
                                vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled,
                                "tonemapped, before anti-aliasing")),
      inputRef_(graph.image("tonemapped", input_)) {}

void MorphologicalAntialiasing::declare(FrameGraph& graph, const GraphImage& ldr, const GraphImage& depth,
                                        vk::Sampler linearClamp, vk::Sampler nearest) const {
  shader::MorphologicalParams params = kParams;
  params.size = {ldr.image->extent.width, ldr.image->extent.height};
  graph.pass(passes::kAntialias, [this, ldr, depth, params, linearClamp, nearest](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .sampledImage(0, inputRef_, linearClamp, Use::ComputeSample)
                        .storageImage(1, ldr, Use::ComputeWrite)
                        .sampledImage(2, depth, nearest, Use::ComputeSample);
    return [this, &set, params](PassContext& pc) {
      gpu::bindPipeline(pc.cmd, pipeline_, params);
      set.bind(pc.cmd, pipeline_, pc.descriptors);
      gpu::dispatchCovering(pc.cmd, pipeline_, params.size.x, params.size.y);
    };
  });
}

}  // namespace tp::render
