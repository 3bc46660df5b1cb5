#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "graph/frame_graph.hpp"
#include "render/env_prefilter.hpp"
#include "render/pass_kinds.hpp"

namespace tp::render {

// How the prefilter estimates each texel (glossy_prefilter.comp): directions
// drawn from the environment's luminance and from the lobe, combined by the
// balance heuristic; either may be 0 (not both).
struct GlossySampling {
  uint32_t environment = 64;
  uint32_t lobe = 64;
};

// The glossy map's size for a sky `skyWidth` texels wide: the largest power
// of two within it, at most kGlossyMaxWidth and at least kGlossyMinWidth.
uint32_t glossyBaseWidth(uint32_t skyWidth);
// Its levels, down to kGlossyMinWidth wide.
uint32_t glossyLevelCount(uint32_t baseWidth);

// The glossy environment (shared/glossy.h) built in compute from a sky
// texture: the environment sampler's CDFs (render/env_prefilter), then one
// dispatch per level of the equirectangular mip chain.
class GlossyPrefilter {
 public:
  GlossyPrefilter(const gpu::Context& ctx, uint32_t skyWidth, uint32_t skyHeight, GlossySampling sampling = {});

  // The map: sampled with textureLod by the shaders (shared/glossy.h's lod).
  const gpu::Image& map() const { return map_; }
  uint32_t levels() const { return map_.mipLevels; }

  // The CDFs of `sky` (in the shader-read layout) and every level of the map
  // (in the general layout): the commands alone, the caller's barriers around them.
  void record(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& descriptors, const gpu::Image& sky,
              vk::Sampler sampler);
  // The cached pass "glossy prefilter" (or `kind`): it reads the sky and
  // writes the map, so it runs on the first frame and again only when the
  // sky changes.
  void declare(FrameGraph& graph, const GraphImage& sky, vk::Sampler sampler, const GraphImage& map,
               const PassKind& kind = passes::kGlossyPrefilter);

  // Outside a frame (tests, bench): prefilters `sky` in a submission of its
  // own and reads every level back (RGBA, rows top to bottom); `milliseconds`
  // gets the GPU time of the CDFs and the levels when given.
  std::vector<std::vector<glm::vec4>> prefilterAndRead(const gpu::Image& sky, vk::Sampler sampler,
                                                       double* milliseconds = nullptr);

 private:
  const gpu::Context& ctx_;
  GlossySampling sampling_;
  EnvPrefilter cdf_;
  gpu::Pipeline pipeline_;
  gpu::Image map_;
  gpu::DescriptorArena descriptors_;  // prefilterAndRead's
};

}  // namespace tp::render
