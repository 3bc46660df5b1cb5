#pragma once
// The frame's last pass over its HDR colour (resolve.comp), each pixel read
// once: the AO, when it is taken after the water (AoForResolve), the haze
// (sky.haze_distance), the colour stored back where a frame reads it back,
// and the tonemap into the 8-bit image (exposure, ACES filmic fit, sRGB).
// What a frame asks for picks the pipeline: specialized, a frame shown in
// the viewer does not store its HDR colour, and one written to EXR alone
// does not tonemap.
//
// With ResolveTiles, a frame that only tonemaps resolves only the tiles
// whose pixels may differ from the last frame's, and leaves the rest of the
// 8-bit image as it is (docs/frame-skipping.md, "The resolve of a still
// frame"). A pixel's result depends on its colour, depth and ambient, the
// AO, the frame's uniforms, the sky and the camera's medium. Outside what
// the pool, the objects and the water draw, the colour, depth and ambient
// are the ground's copy; so when none of the ground's images, the AO, the
// uniforms, the sky and the medium changed since the last frame, only the
// pixels those draw in this frame or drew in the last one can differ.
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "render/ambient_occlusion.hpp"
#include "render/screen_tiles.hpp"
#include "render/surfaces.hpp"
#include "render/water_deferred.hpp"
#include "scene/scene.hpp"
#include "shared/resolve.h"

namespace tp::render {

// What the resolve needs to work on the changed tiles alone.
struct ResolveTiles {
  const WaterDeferred* water;          // its tags: the tiles the water drew over
  std::vector<ResourceRef> unchanged;  // the inputs that, changed, change the pixels outside
};

class FrameResolve {
 public:
  // `ao`: the AO this pass takes from the frame; none when there is none,
  // or a pass of its own applied it before the water. `tiles`: none to
  // resolve the whole frame always.
  FrameResolve(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, vk::Extent2D frame,
               std::optional<AoForResolve> ao, std::optional<ResolveTiles> tiles);
  // Its pass, from `frame`'s colour into `ldr` (and back into the colour).
  void declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in, const GraphImage& ldr);
  // What the next frame reads back or shows: set before it records.
  void setWanted(bool hdr, bool ldr) {
    wantHdr_ = hdr;
    wantLdr_ = ldr;
  }
  // The next frame's number among the renderer's frames, and the pixels
  // that the pool and the objects may draw in it.
  void setFrame(uint64_t number, const PixelRect& drawn) {
    frame_ = number;
    drawn_ = drawn;
  }
  // Whether the next frame's pass stores the HDR colour, changed in place.
  bool storesHdr() const { return outputs() != kLdrOnly; }
  // The tiles the last frame resolved, of all its tiles (with ResolveTiles:
  // known once it has finished, read from the GPU).
  struct Resolved {
    uint32_t tiles = 0, of = 0;
  };
  Resolved lastResolved() const;

 private:
  // Whether the pass changes the colour (AO or haze): else it only reads it.
  bool changesColor() const { return ao_.has_value() || haze_; }
  enum Outputs { kBoth, kHdrOnly, kLdrOnly, kOutputsCount };
  Outputs outputs() const;
  // Whether this frame may resolve the changed tiles alone: asked as the
  // list records, after every pass before it has.
  bool changedTilesAlone(const FrameGraph& graph) const;
  void declareList(FrameGraph& graph);

  std::optional<AoForResolve> ao_;
  bool haze_;
  shader::ResolveParams params_;
  // Specialized by what they write: the HDR colour and the 8-bit image, the
  // colour alone, the 8-bit image alone.
  std::array<std::optional<gpu::Pipeline>, kOutputsCount> pipelines_;
  bool wantHdr_ = true, wantLdr_ = true;

  // With ResolveTiles: the list of tiles to resolve, and what the last frame's list saw.
  std::optional<ResolveTiles> tiles_;
  ScreenTiles screen_;
  std::optional<gpu::Pipeline> listPipeline_;
  gpu::Buffer list_;
  GraphBuffer listRef_;
  uint64_t frame_ = 0;
  PixelRect drawn_;
  struct Last {
    uint64_t frame = 0;
    PixelRect drawn;
    uint32_t waterTag = 0;
    std::vector<uint64_t> versions;  // of ResolveTiles::unchanged
    bool wroteLdr = false;
  };
  std::optional<Last> last_;
};

}  // namespace tp::render
