#pragma once
// The water surface seen from above, accurate refraction, shaded once per
// pixel. On lavapipe a fragment shader runs for every 4x4 block each
// triangle touches, so the water mesh's small triangles, shaded forward,
// cost several times the pixels they cover (docs/viewer.md). Here the mesh's
// front faces only store what shading needs (water_surface_gbuffer.frag,
// lib/water_gbuffer.glsl) and tag the tiles they cover; the tagged tiles
// are listed (screen_tile_list.comp) and each covered pixel is shaded by
// the forward shader's own code (water_surface_deferred.comp). Same bits as
// water_surface.frag: the ray differentials come from the fragment stage.
#include <array>
#include <cstdint>

#include "gpu/context.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "graph/frame_graph.hpp"
#include "render/pool.hpp"
#include "render/screen_tiles.hpp"
#include "render/surfaces.hpp"
#include "render/water_draw.hpp"
#include "shared/water_surface.h"

namespace tp::render {

class WaterDeferred {
 public:
  // `needs`: the water's shader variant and specialization (as water_surface.frag's).
  WaterDeferred(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D frame, FragmentNeeds needs);
  // The G-buffer, tile-list and shading passes, in that order.
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const WaterDraw& water, const PoolDraw& pool,
               const FrameInputs& in) const;
  // The tiles the G-buffer pass tagged, each with the tag of the last frame
  // that drew the water over it (0: none), and that tag.
  const GraphBuffer& tileTags() const { return tileTagsRef_; }
  uint32_t tag() const { return tag_; }

 private:
  // The surface's push constants with this frame's tag and the tiles' row.
  shader::WaterSurfaceParams params(const WaterDraw& water) const;

  gpu::Pipeline gbufferPipeline_, tilesPipeline_, shadePipeline_;
  bool clearAmbient_;  // FragmentNeeds::clearAmbient
  std::array<gpu::Image, TP_WATER_GBUFFER_TARGETS> gbuffer_;
  std::array<GraphImage, TP_WATER_GBUFFER_TARGETS> gbufferRefs_;
  gpu::Buffer tileTags_, tileList_;
  GraphBuffer tileTagsRef_, tileListRef_;
  ScreenTiles tiles_;
  // Each frame's G-buffer pass takes the next tag (1 to kLastTag, then 1
  // again); texels and tiles it did not write keep older ones.
  mutable uint32_t tag_ = 0;
};

}  // namespace tp::render
