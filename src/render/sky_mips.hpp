#pragma once
// The sky texture's mip chain (sky_mips.comp): each level the mean of the
// level above it, 2x2 texels to one, so that a ray whose direction spreads
// over many texels (through a lens, skyFiltered in lib/scene_rays.glsl)
// looks up their average instead of one of them.
#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"

namespace tp::render {

// Levels down to a side of one texel: a 2:1 equirectangular texture's
// last level is 2x1.
uint32_t skyMipLevels(vk::Extent2D extent);

class SkyMips {
 public:
  explicit SkyMips(const gpu::Context& ctx);
  // Records levels 1 and on from level 0, which a compute shader or a
  // transfer wrote before (a barrier from the compute writes is recorded
  // here; a transfer's is the caller's), the image in the general layout.
  void record(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& descriptors, const gpu::Image& sky) const;

 private:
  gpu::Pipeline pipeline_;
};

}  // namespace tp::render
