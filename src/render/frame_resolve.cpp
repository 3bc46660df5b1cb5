#include "render/frame_resolve.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shared/specialization.h"

namespace tp::render {

FrameResolve::FrameResolve(const gpu::Context& ctx, const scene::Scene& scene, std::optional<AoForResolve> ao)
    : ao_(std::move(ao)), haze_(scene.sky.hazeDistance > 0.0f) {
  params_.size = glm::uvec4(0u);
  params_.shape = glm::vec4(0.0f);
  if (ao_) {
    params_.size = ao_->params.size;
    params_.shape = ao_->params.shape;
  }
  params_.look = glm::vec4(scene.sky.hazeDistance, scene.render.exposure, 0.0f, 0.0f);
  const std::string module = !ao_ ? "resolve.comp" : ao_->upsample ? "resolve.ao_upsample.comp" : "resolve.ao.comp";
  auto make = [&](bool hdr, bool ldr) {
    return gpu::createComputePipeline(ctx, module, sizeof(shader::ResolveParams),
                                      gpu::Specialization()
                                          .set(TP_SPEC_HAZE, uint32_t(haze_))
                                          .set(TP_SPEC_STORE_HDR, uint32_t(hdr))
                                          .set(TP_SPEC_WRITE_LDR, uint32_t(ldr)));
  };
  pipelines_[kLdrOnly] = make(false, true);
  // A pass that leaves the colour as it is has nothing to store.
  if (changesColor()) {
    pipelines_[kBoth] = make(true, true);
    pipelines_[kHdrOnly] = make(true, false);
  }
}

const gpu::Pipeline& FrameResolve::pipeline() const {
  if (!changesColor() || !wantHdr_) return *pipelines_[kLdrOnly];
  return *pipelines_[wantLdr_ ? kBoth : kHdrOnly];
}

void FrameResolve::declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in,
                           const GraphImage& ldr) const {
  shader::ResolveParams params = params_;
  params.size.x = frame.color.image->extent.width;
  params.size.y = frame.color.image->extent.height;
  graph.pass(passes::kResolve, [this, frame, in, ldr, params](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .storageImage(0, frame.color, changesColor() ? Use::ComputeReadWrite : Use::ComputeRead)
                        .storageImage(1, ldr, Use::ComputeWrite)
                        .uniformBuffer(2, in.uniforms, Use::HostData)
                        .sampledImage(3, frame.depth, in.nearest, Use::ComputeSample)
                        .sampledImage(4, in.sky, in.equirect, Use::ComputeSample)
                        .uniformBuffer(5, in.medium, Use::ComputeUniformRead);
    if (ao_) {
      set.storageImage(6, ao_->ambient, Use::ComputeRead).storageImage(7, ao_->ao, Use::ComputeRead);
      if (ao_->upsample) set.storageImage(8, ao_->lowViewDepth, Use::ComputeRead);
    }
    return [this, &set, params](PassContext& pc) {
      const gpu::Pipeline& p = pipeline();
      gpu::bindPipeline(pc.cmd, p, params);
      set.bind(pc.cmd, p, pc.descriptors);
      gpu::dispatchCovering(pc.cmd, p, params.size.x, params.size.y);
    };
  });
}

}  // namespace tp::render
