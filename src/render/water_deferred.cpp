#include "render/water_deferred.hpp"

#include <vector>

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "render/pass_kinds.hpp"
#include "shared/screen_tiles.h"

namespace tp::render {
namespace {

constexpr vk::Format kWaterGbufferFormat = vk::Format::eR32G32B32A32Sfloat;
// The tag is stored as a float in the G-buffer: exact up to 2^24. When it
// comes round to 1 again the tag texels are cleared, so no texel left from
// the last round can pass for this frame's.
constexpr uint32_t kLastTag = (1u << 24) - 1u;

gpu::GraphicsPipelineDesc gbufferPipeline() {
  return {.vertexShader = "water_surface.vert",
          .fragmentShader = "water_surface_gbuffer.frag",
          .pushSize = sizeof(shader::WaterSurfaceParams),
          .colorFormats = std::vector<vk::Format>(TP_WATER_GBUFFER_TARGETS, kWaterGbufferFormat),
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true,
          .topology = vk::PrimitiveTopology::eTriangleStrip,
          .cullMode = vk::CullModeFlagBits::eBack};
}

}  // namespace

WaterDeferred::WaterDeferred(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D frame, FragmentNeeds needs)
    : gbufferPipeline_(gpu::createGraphicsPipeline(ctx, gbufferPipeline())),
      tilesPipeline_(gpu::createComputePipeline(ctx, "screen_tile_list.comp", sizeof(shader::ScreenTileListParams))),
      shadePipeline_(gpu::createComputePipeline(ctx, fragmentVariant("water_surface_deferred.comp", needs),
                                                sizeof(shader::WaterSurfaceParams), fragmentSpecialization(needs))),
      clearAmbient_(needs.clearAmbient),
      tiles_(frame) {
  for (size_t i = 0; i < gbuffer_.size(); ++i) {
    const std::string name = "water g-buffer " + std::to_string(i);
    gbuffer_[i] = gpu::createImage2D(ctx, frame, kWaterGbufferFormat,
                                     vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eStorage, name);
    gbufferRefs_[i] = graph.image(name, gbuffer_[i]);
  }
  // Zero: no frame's tag.
  tileTags_ =
      gpu::createFilledBuffer(ctx, std::vector<uint32_t>(tiles_.count, 0u), vk::BufferUsageFlagBits::eStorageBuffer,
                              gpu::MemoryUse::Device, "water shading tile tags");
  tileList_ = gpu::createBuffer(ctx, (TP_SCREEN_TILE_LIST_HEADER + tiles_.count) * sizeof(uint32_t),
                                vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer,
                                gpu::MemoryUse::Device, "water shading tiles");
  tileTagsRef_ = graph.buffer("water shading tile tags", tileTags_);
  tileListRef_ = graph.buffer("water shading tiles", tileList_);
}

shader::WaterSurfaceParams WaterDeferred::params(const WaterDraw& water) const {
  shader::WaterSurfaceParams p = water.params;
  p.grid.z = tag_;
  p.grid.w = tiles_.perRow;
  return p;
}

void WaterDeferred::declare(FrameGraph& graph, const SurfaceTargets& targets, const WaterDraw& water,
                            const PoolDraw& pool, const FrameInputs& in) const {
  graph.pass(passes::kWaterGbuffer, [this, targets, water, in](PassBuilder& pass) {
    const gpu::Image& depth = pass.attach(targets.depth, Use::DepthReadWrite);
    for (const GraphImage& g : gbufferRefs_) pass.attach(g, Use::ColorReadWrite);
    Bindings& set = pass.bindings()
                        .uniformBuffer(0, in.uniforms, Use::HostData)
                        .storageBuffer(2, water.state, Use::VertexStorageRead)
                        .storageBuffer(9, tileTagsRef_, Use::FragmentStorageWrite);
    return [this, water, &depth, &set](PassContext& pc) {
      tag_ = tag_ == kLastTag ? 1u : tag_ + 1u;
      std::vector<vk::RenderingAttachmentInfo> colors;
      for (const gpu::Image& g : gbuffer_) {
        // The tag texels cleared at the start of each round of tags.
        const bool clear = &g == &gbuffer_[0] && tag_ == 1u;
        colors.push_back(attachment(g, vk::ImageLayout::eColorAttachmentOptimal,
                                    clear ? vk::AttachmentLoadOp::eClear : vk::AttachmentLoadOp::eLoad,
                                    vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}}));
      }
      const auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
      renderTo(pc.cmd, colors, &depthTarget, depth.extent, [&] {
        gpu::bindPipeline(pc.cmd, gbufferPipeline_, params(water));
        set.bind(pc.cmd, gbufferPipeline_, pc.descriptors);
        drawWater(pc.cmd, water);
      });
    };
  });
  graph.pass(passes::kWaterTiles, [this](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .storageBuffer(0, tileTagsRef_, Use::ComputeRead)
                        .storageBuffer(1, tileListRef_, Use::ComputeWrite);
    return [this, &set](PassContext& pc) {
      const shader::ScreenTileListParams params{.tags = {tag_, tag_, tiles_.count, tiles_.perRow}, .rect = {}};
      gpu::bindPipeline(pc.cmd, tilesPipeline_, params);
      set.bind(pc.cmd, tilesPipeline_, pc.descriptors);
      gpu::dispatch(pc.cmd, 1);
    };
  });
  graph.pass(passes::kWater, [this, targets, water, pool, in](PassBuilder& pass) {
    Bindings& set = pass.bindings()
                        .uniformBuffer(0, in.uniforms, Use::HostData)
                        .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData)
                        .sampledImage(1, in.sky, in.equirect, Use::ComputeSample)
                        .constantBuffer(3, *pool.uniforms)
                        .constantBuffer(4, *pool.objects)
                        .sampledImage(6, pool.caustics, in.clamp, Use::ComputeSample)
                        .sampledImage(7, in.glossy, in.equirect, Use::ComputeSample)
                        .constantStorageBuffer(8, *pool.floorVertices)
                        .storageImage(9, targets.color, Use::ComputeReadWrite)
                        .storageBuffer(15, tileListRef_, Use::ComputeReadIndirect);
    for (uint32_t i = 0; i < TP_WATER_GBUFFER_TARGETS; ++i) set.storageImage(10 + i, gbufferRefs_[i], Use::ComputeRead);
    if (clearAmbient_) set.storageImage(16, targets.ambient, Use::ComputeReadWrite);
    return [this, water, &set](PassContext& pc) {
      gpu::bindPipeline(pc.cmd, shadePipeline_, params(water));
      set.bind(pc.cmd, shadePipeline_, pc.descriptors);
      gpu::dispatchIndirect(pc.cmd, tileList_.handle(), 0);
    };
  });
}

}  // namespace tp::render
