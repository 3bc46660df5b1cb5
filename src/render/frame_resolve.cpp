#include "render/frame_resolve.hpp"

#include "gpu/barriers.hpp"
#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shared/specialization.h"

namespace tp::render {

FrameResolve::FrameResolve(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, vk::Extent2D frame,
                           std::optional<AoForResolve> ao, std::optional<ResolveTiles> tiles)
    : ao_(std::move(ao)), haze_(scene.sky.hazeDistance > 0.0f), tiles_(std::move(tiles)), screen_(frame) {
  params_.size = glm::uvec4(0u);
  params_.shape = glm::vec4(0.0f);
  if (ao_) {
    params_.size = ao_->params.size;
    params_.shape = ao_->params.shape;
  }
  params_.look = glm::vec4(scene.sky.hazeDistance, scene.render.exposure, 0.0f, 0.0f);
  const std::string base = !ao_ ? "resolve" : ao_->upsample ? "resolve.ao_upsample" : "resolve.ao";
  const std::string module = base + (tiles_ ? ".listed.comp" : ".comp");
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
  if (tiles_) {
    listPipeline_ = gpu::createComputePipeline(ctx, "screen_tile_list.comp", sizeof(shader::ScreenTileListParams));
    // Read by the host after the frame (lastResolved).
    list_ = gpu::createBuffer(ctx, (TP_SCREEN_TILE_LIST_HEADER + screen_.count) * sizeof(uint32_t),
                              vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer,
                              gpu::MemoryUse::Readback, "resolve tiles");
    listRef_ = graph.buffer("resolve tiles", list_);
  }
}

FrameResolve::Outputs FrameResolve::outputs() const {
  if (!changesColor() || !wantHdr_) return kLdrOnly;
  return wantLdr_ ? kBoth : kHdrOnly;
}

FrameResolve::Resolved FrameResolve::lastResolved() const {
  if (!tiles_ || !last_) return {};
  return {static_cast<const uint32_t*>(list_.mapped)[0], screen_.count};
}

bool FrameResolve::changedTilesAlone(const FrameGraph& graph) const {
  // The 8-bit image holds the last frame's, which was the one before this:
  // only tiles that changed need it again. A frame that stores its HDR colour
  // stores every pixel's.
  if (!last_ || !last_->wroteLdr || last_->frame + 1 != frame_ || outputs() != kLdrOnly) return false;
  for (size_t k = 0; k < tiles_->unchanged.size(); ++k) {
    if (graph.versionOf(tiles_->unchanged[k]) != last_->versions[k]) return false;
  }
  return true;
}

void FrameResolve::declareList(FrameGraph& graph) {
  graph.pass(passes::kResolveTiles, [this, &graph](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .storageBuffer(0, tiles_->water->tileTags(), Use::ComputeRead)
                        .storageBuffer(1, listRef_, Use::ComputeWrite);
    return [this, &graph, &set](PassContext& pc) {
      const uint32_t tag = tiles_->water->tag();
      shader::ScreenTileListParams params{.tags = {tag, tag, screen_.count, screen_.perRow}, .rect = screen_.all()};
      if (changedTilesAlone(graph)) {
        // The pixels the water drew this frame and the last, the pool's and
        // the objects' this frame and the last.
        params.tags.y = last_->waterTag;
        params.rect = screen_.covering(united(drawn_, last_->drawn));
      }
      Last seen{.frame = frame_, .drawn = drawn_, .waterTag = tag, .versions = {}, .wroteLdr = outputs() != kHdrOnly};
      for (ResourceRef ref : tiles_->unchanged) seen.versions.push_back(graph.versionOf(ref));
      last_ = std::move(seen);
      gpu::bindPipeline(pc.cmd, *listPipeline_, params);
      set.bind(pc.cmd, *listPipeline_, pc.descriptors);
      gpu::dispatch(pc.cmd, 1);
    };
  });
}

void FrameResolve::declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in,
                           const GraphImage& ldr) {
  if (tiles_) declareList(graph);
  shader::ResolveParams params = params_;
  params.size.x = frame.color.image->extent.width;
  params.size.y = frame.color.image->extent.height;
  graph.pass(passes::kResolve, [this, frame, in, ldr, params](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .storageImage(0, frame.color, changesColor() ? Use::ComputeReadWrite : Use::ComputeRead)
                        // Listed, the tiles left out keep the last frame's pixels.
                        .storageImage(1, ldr, tiles_ ? Use::ComputeReadWrite : Use::ComputeWrite)
                        .uniformBuffer(2, in.uniforms, Use::HostData)
                        .sampledImage(3, frame.depth, in.nearest, Use::ComputeSample)
                        .sampledImage(4, in.sky, in.equirect, Use::ComputeSample)
                        .uniformBuffer(5, in.medium, Use::ComputeUniformRead);
    if (ao_) {
      set.storageImage(6, ao_->ambient, Use::ComputeRead).storageImage(7, ao_->ao, Use::ComputeRead);
      if (ao_->upsample) set.storageImage(8, ao_->lowViewDepth, Use::ComputeRead);
    }
    if (tiles_) set.storageBuffer(9, listRef_, Use::ComputeReadIndirect);
    return [this, &set, params](PassContext& pc) {
      const gpu::Pipeline& p = *pipelines_[outputs()];
      gpu::bindPipeline(pc.cmd, p, params);
      set.bind(pc.cmd, p, pc.descriptors);
      if (!tiles_) {
        gpu::dispatchCovering(pc.cmd, p, params.size.x, params.size.y);
        return;
      }
      gpu::dispatchIndirect(pc.cmd, list_.handle(), 0);
      // The list's count, for lastResolved.
      const auto toHost = gpu::bufferBarrier(list_.handle(), gpu::access::computeWrite, gpu::access::hostRead);
      gpu::pipelineBarrier(pc.cmd, std::span(&toHost, 1));
    };
  });
}

}  // namespace tp::render
