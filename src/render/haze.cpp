#include "render/haze.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shared/haze.h"

namespace tp::render {

Haze::Haze(const gpu::Context& ctx)
    : pipeline_(gpu::createComputePipeline(ctx, "haze.comp", sizeof(shader::HazeParams))) {}

void Haze::declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in, float hazeDistance) const {
  const vk::Extent2D extent = frame.color.image->extent;
  const shader::HazeParams params{.size = {extent.width, extent.height, 0u, 0u},
                                  .haze = {hazeDistance, 0.0f, 0.0f, 0.0f}};
  graph.pass(passes::kHaze, [this, frame, in, params](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .storageImage(0, frame.color, Use::ComputeReadWrite)
                        .sampledImage(1, frame.depth, in.nearest, Use::ComputeSample)
                        .sampledImage(2, in.sky, in.equirect, Use::ComputeSample)
                        .uniformBuffer(3, in.uniforms, Use::HostData)
                        .uniformBuffer(4, in.medium, Use::ComputeUniformRead);
    return [this, &set, params](PassContext& pc) {
      gpu::bindPipeline(pc.cmd, pipeline_, params);
      set.bind(pc.cmd, pipeline_, pc.descriptors);
      gpu::dispatchCovering(pc.cmd, pipeline_, params.size.x, params.size.y);
    };
  });
}

}  // namespace tp::render
