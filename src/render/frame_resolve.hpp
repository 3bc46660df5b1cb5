#pragma once
// The frame's last pass over its HDR colour (resolve.comp), each pixel read
// once: the AO, when it is taken after the water (AoForResolve), the haze
// (sky.haze_distance), the colour stored back where a frame reads it back,
// and the tonemap into the 8-bit image (exposure, ACES filmic fit, sRGB).
// What a frame asks for picks the pipeline: specialized, a frame shown in
// the viewer does not store its HDR colour, and one written to EXR alone
// does not tonemap.
#include <array>
#include <optional>

#include "render/ambient_occlusion.hpp"
#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shared/resolve.h"

namespace tp::render {

class FrameResolve {
 public:
  // `ao`: the AO this pass takes from the frame; none when there is none,
  // or a pass of its own applied it before the water.
  FrameResolve(const gpu::Context& ctx, const scene::Scene& scene, std::optional<AoForResolve> ao);
  // Its pass, from `frame`'s colour into `ldr` (and back into the colour).
  void declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in, const GraphImage& ldr) const;
  // What the next frame reads back or shows: set before it records.
  void setWanted(bool hdr, bool ldr) {
    wantHdr_ = hdr;
    wantLdr_ = ldr;
  }

 private:
  // Whether the pass changes the colour (AO or haze): else it only reads it.
  bool changesColor() const { return ao_.has_value() || haze_; }
  const gpu::Pipeline& pipeline() const;

  std::optional<AoForResolve> ao_;
  bool haze_;
  shader::ResolveParams params_;
  // Specialized by what they write: the HDR colour and the 8-bit image, the
  // colour alone, the 8-bit image alone.
  enum Outputs { kBoth, kHdrOnly, kLdrOnly, kOutputsCount };
  std::array<std::optional<gpu::Pipeline>, kOutputsCount> pipelines_;
  bool wantHdr_ = true, wantLdr_ = true;
};

}  // namespace tp::render
