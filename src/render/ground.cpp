#include "render/ground.hpp"

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
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
  needs.glassShadows = false;
  return needs;
}

}  // namespace

Ground::Ground(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, FragmentNeeds needs,
               vk::Extent2D frame, bool gbuffer)
    : params_(groundParams(scene)),
      pipeline_(gpu::createGraphicsPipeline(
          ctx, opaquePipeline("ground.vert", "ground.frag", sizeof(shader::GroundParams), groundNeeds(needs)))) {
  // Drawn into, then copied from.
  const auto usage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc;
  color_ = gpu::createImage2D(ctx, frame, kHdrFormat, usage, "ground color");
  depth_ = gpu::createImage2D(ctx, frame, kDepthFormat,
                              vk::ImageUsageFlagBits::eDepthStencilAttachment | vk::ImageUsageFlagBits::eTransferSrc,
                              "ground depth");
  own_.color = graph.image("ground color", color_);
  own_.depth = graph.image("ground depth", depth_);
  if (gbuffer) {
    normal_ = gpu::createImage2D(ctx, frame, kGbufferFormat, usage, "ground view normal");
    ambient_ = gpu::createImage2D(ctx, frame, kGbufferFormat, usage, "ground ambient");
    own_.normal = graph.image("ground view normal", normal_);
    own_.ambient = graph.image("ground ambient", ambient_);
  }
  if (needs.sphereShadows || needs.boxShadows || needs.glassShadows) {
    unshadowed_.emplace(gpu::createGraphicsPipeline(
        ctx, opaquePipeline("ground.vert", "ground.frag", sizeof(shader::GroundParams), unshadowedNeeds(needs))));
  }
}

void Ground::declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
                     std::function<bool()> outOfObjectShadows,
                     const std::function<std::function<void(PassContext&)>(PassBuilder&)>& sky,
                     std::function<std::optional<PixelRect>()> copyOnly) const {
  graph.pass(passes::kGround,
             [this, in, outOfObjectShadows, &sky](PassBuilder& pass) {
               attachSurfaces(pass, own_, true);
               Bindings& set = pass.bindings()
                                   .uniformBuffer(0, in.uniforms, Use::HostData)
                                   .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData);
               auto drawSky = sky(pass);
               return [this, &set, outOfObjectShadows, drawSky](PassContext& pc) {
                 drawnSinceCopy_ = true;
                 const gpu::Pipeline& pipeline = unshadowed_ && outOfObjectShadows() ? *unshadowed_ : pipeline_;
                 drawSurfaces(pc.cmd, own_, true, [&] {
                   gpu::bindPipeline(pc.cmd, pipeline, params_);
                   set.bind(pc.cmd, pipeline, pc.descriptors);
                   gpu::draw(pc.cmd, kGroundVertices);
                   drawSky(pc);
                 });
               };
             },
             {.cached = true, .runIf = {}});
  graph.pass(passes::kGroundCopy, [this, targets, copyOnly](PassBuilder& pass) {
    std::vector<std::pair<const gpu::Image*, const gpu::Image*>> copies;
    // Copied in part, the targets keep the rest.
    const Use write = copyOnly ? Use::TransferWritePart : Use::TransferWrite;
    auto copy = [&](const GraphImage& from, const GraphImage& to) {
      if (from) copies.emplace_back(&pass.attach(from, Use::TransferRead), &pass.attach(to, write));
    };
    copy(own_.color, targets.color);
    copy(own_.depth, targets.depth);
    copy(own_.normal, targets.normal);
    copy(own_.ambient, targets.ambient);
    return [this, copies, copyOnly](PassContext& pc) {
      const std::optional<PixelRect> only = copyOnly && !drawnSinceCopy_ ? copyOnly() : std::nullopt;
      drawnSinceCopy_ = false;
      for (const auto& [from, to] : copies) {
        if (!only) {
          gpu::recordImageCopy(pc.cmd, *from, *to);
        } else if (!only->empty()) {
          gpu::recordImageCopy(pc.cmd, *from, *to, only->lo, only->hi);
        }
      }
    };
  });
}

}  // namespace tp::render
