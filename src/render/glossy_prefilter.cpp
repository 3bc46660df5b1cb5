#include "render/glossy_prefilter.hpp"

#include <bit>
#include <glm/gtc/packing.hpp>
#include <stdexcept>

#include "gpu/barriers.hpp"
#include "gpu/commands.hpp"
#include "gpu/submit.hpp"
#include "gpu/timer.hpp"
#include "render/pass_kinds.hpp"
#include "render/surfaces.hpp"
#include "shared/glossy.h"

namespace tp::render {

uint32_t glossyBaseWidth(uint32_t skyWidth) {
  return std::clamp(std::bit_floor(skyWidth), shader::kGlossyMinWidth, shader::kGlossyMaxWidth);
}

uint32_t glossyLevelCount(uint32_t baseWidth) { return uint32_t(std::bit_width(baseWidth / shader::kGlossyMinWidth)); }

GlossyPrefilter::GlossyPrefilter(const gpu::Context& ctx, uint32_t skyWidth, uint32_t skyHeight,
                                 GlossySampling sampling)
    : ctx_(ctx),
      sampling_(sampling),
      cdf_(ctx, skyWidth, skyHeight, 1),
      pipeline_(gpu::createComputePipeline(ctx, "glossy_prefilter.comp", sizeof(shader::GlossyParams))),
      descriptors_(ctx) {
  if (sampling.environment + sampling.lobe == 0) throw std::invalid_argument("the glossy prefilter needs samples");
  const uint32_t width = glossyBaseWidth(skyWidth);
  map_ = gpu::createImage2D(
      ctx, {width, width / 2}, kSkyFormat,
      vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferSrc,
      "glossy environment", glossyLevelCount(width));
}

void GlossyPrefilter::record(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& descriptors,
                             const gpu::Image& sky, vk::Sampler sampler) {
  cdf_.recordCdf(cmd, sky, sampler);
  const uint32_t base = map_.extent.width;
  for (uint32_t level = 0; level < map_.mipLevels; ++level) {
    const glm::uvec2 size(base >> level, (base / 2) >> level);
    const shader::GlossyParams params{glm::uvec4(sky.extent.width, sky.extent.height, size),
                                      glm::uvec4(sampling_.environment, sampling_.lobe, level, 0u),
                                      glm::vec4(shader::glossyLevelExponent(base, level), 0.0f, 0.0f, 0.0f)};
    gpu::bindPipeline(cmd, pipeline_, params);
    gpu::DescriptorWrites()
        .sampledImage(0, sky, sampler)
        .storageBuffer(1, cdf_.conditionalBuffer())
        .storageBuffer(2, cdf_.marginalBuffer())
        .storageImageLevel(3, map_, level)
        .bind(cmd, pipeline_, descriptors);
    gpu::dispatchCovering(cmd, pipeline_, size.x, size.y);
  }
}

void GlossyPrefilter::declare(FrameGraph& graph, const GraphImage& sky, vk::Sampler sampler, const GraphImage& map,
                              const PassKind& kind) {
  // The prefilter binds its own sets, level by level (record()).
  graph.pass(kind,
             [this, sky, sampler, map](PassBuilder& pass) {
               const gpu::Image& source = pass.attach(sky, Use::ComputeSample);
               pass.attach(map, Use::ComputeWrite);
               return [this, &source, sampler](PassContext& pc) { record(pc.cmd, pc.descriptors, source, sampler); };
             },
             {.cached = true, .runIf = {}});
}

std::vector<std::vector<glm::vec4>> GlossyPrefilter::prefilterAndRead(const gpu::Image& sky, vk::Sampler sampler,
                                                                      double* milliseconds) {
  const uint32_t base = map_.extent.width;
  vk::DeviceSize texels = 0;
  for (uint32_t level = 0; level < map_.mipLevels; ++level)
    texels += vk::DeviceSize(base >> level) * ((base / 2) >> level);
  const gpu::Buffer readback = gpu::createBuffer(ctx_, texels * 8, vk::BufferUsageFlagBits::eTransferDst,
                                                 gpu::MemoryUse::Readback, "glossy environment readback");
  gpu::GpuTimer timer(ctx_, 1);
  descriptors_.reset();
  gpu::submitAndWait(
      ctx_,
      [&](const vk::raii::CommandBuffer& cmd) {
        timer.reset(cmd);
        const auto toWrite =
            gpu::imageBarrier(map_.handle(), map_.aspect, gpu::access::none, vk::ImageLayout::eUndefined,
                              gpu::access::computeWrite, vk::ImageLayout::eGeneral);
        gpu::pipelineBarrier(cmd, {}, std::span(&toWrite, 1));
        const uint32_t scope = timer.begin(cmd, "glossy prefilter");
        record(cmd, descriptors_, sky, sampler);
        timer.end(cmd, scope);
        const auto toCopy =
            gpu::imageBarrier(map_.handle(), map_.aspect, gpu::access::computeWrite, vk::ImageLayout::eGeneral,
                              gpu::access::transferRead, vk::ImageLayout::eTransferSrcOptimal);
        gpu::pipelineBarrier(cmd, {}, std::span(&toCopy, 1));
        vk::DeviceSize offset = 0;
        for (uint32_t level = 0; level < map_.mipLevels; ++level) {
          const uint32_t w = base >> level, h = (base / 2) >> level;
          cmd.copyImageToBuffer(
              map_.handle(), vk::ImageLayout::eTransferSrcOptimal, readback.handle(),
              vk::BufferImageCopy{
                  .bufferOffset = offset, .imageSubresource = {map_.aspect, level, 0, 1}, .imageExtent = {w, h, 1}});
          offset += vk::DeviceSize(w) * h * 8;
        }
        const auto toHost = gpu::bufferBarrier(readback.handle(), gpu::access::transferWrite, gpu::access::hostRead);
        gpu::pipelineBarrier(cmd, std::span(&toHost, 1));
      },
      "glossy prefilter");
  if (milliseconds) *milliseconds = timer.read().front().milliseconds;
  std::vector<std::vector<glm::vec4>> levels;
  const auto* halves = static_cast<const glm::uint64*>(readback.mapped);
  for (uint32_t level = 0; level < map_.mipLevels; ++level) {
    const size_t n = size_t(base >> level) * ((base / 2) >> level);
    std::vector<glm::vec4> texelsOfLevel(n);
    for (size_t k = 0; k < n; ++k) texelsOfLevel[k] = glm::unpackHalf4x16(halves[k]);
    halves += n;
    levels.push_back(std::move(texelsOfLevel));
  }
  return levels;
}

}  // namespace tp::render
