#pragma once
// The frame's own images: the HDR colour and depth every surface draws into,
// the G-buffer beside them when something reads it (SSAO), and the LDR
// preview; with the readbacks of the HDR and LDR images.
#include "graph/readback.hpp"
#include "render/surfaces.hpp"

namespace tp::render {

class FrameTargets {
 public:
  // `sampledDepth`: SSAO or the morphological anti-aliasing samples the depth
  // target, and a frame may read it back.
  FrameTargets(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D extent, bool gbuffer, bool sampledDepth);
  const SurfaceTargets& surfaces() const { return surfaces_; }
  const GraphImage& ldr() const { return ldrRef_; }
  // The readbacks of the HDR colour and the LDR preview, and their passes.
  void declareReadbacks(FrameGraph& graph) const;
  const Readback& hdrReadback() const { return hdrReadback_; }
  const Readback& ldrReadback() const { return ldrReadback_; }

 private:
  gpu::Image color_, depth_, normal_, ambient_, ldr_;
  SurfaceTargets surfaces_;
  GraphImage ldrRef_;
  Readback hdrReadback_, ldrReadback_;
};

}  // namespace tp::render
