#pragma once
// Screen-space ambient occlusion: SSAO from the opaque surfaces' depth and
// G-buffer, the separable blur, and the AO put into the frame, upsampled
// there depth-aware at half resolution (shaders_glsl/ssao.comp, ao_blur.comp,
// ao_apply.comp, lib/ao_upsample.glsl), unless the resolve pass does that
// after the water (render/frame_resolve.hpp); the upsampled AO as an image
// (ao_upsample.comp) only for its readback; with the readbacks a frame asking for its
// AO uses (declared with them, so the depth read back is the opaque
// surfaces', before the water draws over it).
#include <optional>

#include "graph/readback.hpp"
#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shared/ssao.h"

namespace tp::render {

// What the resolve pass reads to take the AO from the frame's ambient part
// after the water (render/frame_resolve.hpp).
struct AoForResolve {
  GraphImage ambient;       // the G-buffer's ambient part
  GraphImage ao;            // the AO at the AO resolution, blurred
  GraphImage lowViewDepth;  // the SSAO pass's shader::aoViewDepth per AO pixel
  bool upsample;            // the AO is at half resolution
  shader::AoUpsampleParams params;
};

class AmbientOcclusion {
 public:
  // `applyLater`: no pass of its own applies the AO to the frame's colour;
  // the resolve pass does, after the water (forResolve).
  AmbientOcclusion(const gpu::Context& ctx, FrameGraph& graph, const scene::Ao& ao, vk::Extent2D frame,
                   bool applyLater);
  // The SSAO, the blur, the pass that applies the AO (unless applied
  // later) and the readbacks. `surfacesChanged`, asked every frame: false
  // when the opaque surfaces' depth and normals are the same as when the
  // SSAO last ran (render/opaque_geometry.hpp), which leaves the SSAO and
  // its blur out and the AO as they made it.
  void declare(FrameGraph& graph, const SurfaceTargets& surfaces, const FrameInputs& in,
               const std::function<bool()>& surfacesChanged) const;
  // What the resolve pass reads, when it applies the AO (`applyLater`).
  std::optional<AoForResolve> forResolve(const SurfaceTargets& surfaces) const;
  // What a frame requests to read the AO back.
  std::vector<ResourceRef> readbackRefs() const;
  vk::Extent2D lowExtent() const { return low_; }
  // After a frame that requested them: the AO (frame size, after blur and
  // upsample), the unblurred SSAO (lowExtent), and the G-buffer it came from
  // (depth; xyz0 view normal).
  struct Readings {
    std::vector<float> ao, raw, depth, viewNormal;
  };
  Readings read() const;

 private:
  // The AO at the AO resolution after the blur (or the raw AO without one).
  const GraphImage& lowResult() const { return blurred_ ? blurred_ : raw_; }
  // The frame-size AO the apply pass reads.
  const GraphImage& result() const { return full_ ? full_ : lowResult(); }
  void declareFilter(FrameGraph& graph, const PassKind& kind, const gpu::Pipeline& pipeline,
                     const SurfaceTargets& surfaces, const FrameInputs& in, const GraphImage& from,
                     const GraphImage& to, const std::function<void(const vk::raii::CommandBuffer&)>& push,
                     vk::Extent2D size, bool frameDepth, PassOptions options = {}) const;
  void declareApply(FrameGraph& graph, const SurfaceTargets& surfaces, const FrameInputs& in) const;

  scene::Ao ao_;
  vk::Extent2D frame_, low_;
  gpu::Image rawImage_, viewDepthImage_, blurXImage_, blurredImage_, fullImage_;
  // viewDepth_: shader::aoViewDepth per AO pixel; no blur images with the
  // blur off; no full image at full resolution.
  GraphImage raw_, viewDepth_, blurX_, blurred_, full_;
  gpu::Buffer kernel_;
  gpu::Pipeline ssao_, blur_, upsample_;
  std::optional<gpu::Pipeline> apply_;  // none when the AO is applied later
  Readback aoReadback_, rawReadback_, depthReadback_, normalReadback_;
};

}  // namespace tp::render
