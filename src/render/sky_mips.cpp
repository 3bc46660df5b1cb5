#include "render/sky_mips.hpp"

#include <algorithm>
#include <bit>

#include "gpu/barriers.hpp"

namespace tp::render {

uint32_t skyMipLevels(vk::Extent2D extent) { return uint32_t(std::bit_width(std::min(extent.width, extent.height))); }

SkyMips::SkyMips(const gpu::Context& ctx) : pipeline_(gpu::createComputePipeline(ctx, "sky_mips.comp", 0)) {}

void SkyMips::record(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& descriptors,
                     const gpu::Image& sky) const {
  cmd.bindPipeline(pipeline_.bindPoint, *pipeline_.pipeline);
  for (uint32_t level = 1; level < sky.mipLevels; ++level) {
    // The level above, written by the last dispatch (or the sky's), is read.
    gpu::stageBarrier(cmd, gpu::access::computeWrite, gpu::access::computeRead);
    gpu::DescriptorWrites()
        .storageImageLevel(0, sky, level - 1)
        .storageImageLevel(1, sky, level)
        .bind(cmd, pipeline_, descriptors);
    gpu::dispatchCovering(cmd, pipeline_, std::max(sky.extent.width >> level, 1u),
                          std::max(sky.extent.height >> level, 1u));
  }
}

}  // namespace tp::render
