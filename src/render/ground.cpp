#include "render/ground.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/water_model.hpp"

namespace tp::render {

namespace {

// The ground is never in the water: its shader has no scattering variants.
FragmentNeeds groundNeeds(FragmentNeeds surfaces) {
  FragmentNeeds needs = surfaces;
  needs.scattering = false;
  return needs;
}

// The same, out of the objects' shadows: the pool's walls are all that is left to cast one.
FragmentNeeds unshadowedNeeds(FragmentNeeds surfaces) {
  FragmentNeeds needs = groundNeeds(surfaces);
  needs.sphereShadows = false;
  needs.boxShadows = false;
  return needs;
}

}  // namespace

Ground::Ground(const gpu::Context& ctx, const scene::Scene& scene, FragmentNeeds needs)
    : params_(groundParams(scene)),
      pipeline_(gpu::createGraphicsPipeline(
          ctx, opaquePipeline("ground.vert", "ground.frag", sizeof(shader::GroundParams), groundNeeds(needs)))) {
  if (needs.sphereShadows || needs.boxShadows) {
    unshadowed_.emplace(gpu::createGraphicsPipeline(
        ctx, opaquePipeline("ground.vert", "ground.frag", sizeof(shader::GroundParams), unshadowedNeeds(needs))));
  }
}

void Ground::declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
                     std::function<bool()> outOfObjectShadows) const {
  graph.pass(passes::kGround, [this, targets, in, outOfObjectShadows](PassBuilder& pass) {
    attachSurfaces(pass, targets, true);
    Bindings& set = pass.bindings().uniformBuffer(0, in.uniforms, Use::HostData);
    return [this, targets, &set, outOfObjectShadows](PassContext& pc) {
      const gpu::Pipeline& pipeline = unshadowed_ && outOfObjectShadows() ? *unshadowed_ : pipeline_;
      drawSurfaces(pc.cmd, targets, true, [&] {
        gpu::bindPipeline(pc.cmd, pipeline, params_);
        set.bind(pc.cmd, pipeline, pc.descriptors);
        gpu::draw(pc.cmd, kGroundVertices);
      });
    };
  });
}

}  // namespace tp::render
