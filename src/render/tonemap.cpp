#include "render/tonemap.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shared/tonemap.h"

namespace tp::render {

Tonemap::Tonemap(const gpu::Context& ctx)
    : pipeline_(gpu::createComputePipeline(ctx, "tonemap.comp", sizeof(shader::TonemapParams))) {}

void Tonemap::declare(FrameGraph& graph, const GraphImage& hdr, const GraphImage& ldr, float exposure) const {
  const shader::TonemapParams params{
      .size = {hdr.image->extent.width, hdr.image->extent.height}, .exposure = exposure, .pad = 0.0f};
  graph.pass(passes::kTonemap, [this, hdr, ldr, params](PassBuilder& pass) {
    Bindings& set = pass.bindings().storageImage(0, hdr, Use::ComputeRead).storageImage(1, ldr, Use::ComputeWrite);
    return [this, &set, params](PassContext& pc) {
      gpu::bindPipeline(pc.cmd, pipeline_, params);
      set.bind(pc.cmd, pipeline_, pc.descriptors);
      gpu::dispatchCovering(pc.cmd, pipeline_, params.size.x, params.size.y);
    };
  });
}

}  // namespace tp::render
