#include "render/passes.hpp"

#include "gpu/descriptors.hpp"

#include <functional>

namespace tp::render {
namespace {

void setViewport(const vk::raii::CommandBuffer& cmd, vk::Extent2D extent) {
  cmd.setViewport(0, vk::Viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f});
  cmd.setScissor(0, vk::Rect2D{{0, 0}, extent});
}

vk::RenderingAttachmentInfo attachment(const gpu::Image& image, vk::ImageLayout layout, vk::AttachmentLoadOp load,
                                       vk::ClearValue clear = {}) {
  return vk::RenderingAttachmentInfo{.imageView = *image.view,
                                     .imageLayout = layout,
                                     .loadOp = load,
                                     .storeOp = vk::AttachmentStoreOp::eStore,
                                     .clearValue = clear};
}

}  // namespace

SkyPass::SkyPass(const gpu::Context& ctx)
    : pipeline(gpu::createComputePipeline(ctx, "sky.comp", sizeof(shader::SkyParams))) {}

void SkyPass::declare(FrameGraph& graph, ResourceRef skyRef, const gpu::Image& sky,
                      const shader::SkyParams& params) const {
  graph.pass("sky", {{skyRef, Use::ComputeWrite}}, [this, &sky, params](PassContext& pc) {
    const auto& cmd = pc.cmd;
    gpu::bindPipeline(cmd, pipeline, params);
    gpu::DescriptorWrites().storageImage(0, sky).bind(cmd, pipeline, pc.descriptors);
    gpu::dispatchCovering(cmd, pipeline, params.size.x, params.size.y);
  });
}

BackgroundPass::BackgroundPass(const gpu::Context& ctx)
    : pipeline(gpu::createGraphicsPipeline(ctx, {.vertexShader = "fullscreen.vert",
                                                 .fragmentShader = "sky_background.frag",
                                                 .colorFormats = {kHdrFormat}})) {}

void BackgroundPass::declare(FrameGraph& graph, ResourceRef colorRef, const gpu::Image& color, ResourceRef skyRef,
                             const gpu::Image& sky, vk::Sampler sampler, const gpu::Buffer& frameUniforms) const {
  graph.pass("background", {{skyRef, Use::FragmentSample}, {colorRef, Use::ColorWrite}},
             [this, &color, &sky, sampler, &frameUniforms](PassContext& pc) {
               const auto& cmd = pc.cmd;
               auto target = attachment(color, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eDontCare);
               cmd.beginRendering(vk::RenderingInfo{
                   .renderArea = {{0, 0}, color.extent}, .layerCount = 1, .colorAttachmentCount = 1, .pColorAttachments = &target});
               cmd.bindPipeline(pipeline.bindPoint, *pipeline.pipeline);
               gpu::DescriptorWrites().uniformBuffer(0, frameUniforms).sampledImage(1, sky, sampler).bind(cmd, pipeline, pc.descriptors);
               setViewport(cmd, color.extent);
               cmd.draw(3, 1, 0, 0);
               cmd.endRendering();
             });
}

GroundPass::GroundPass(const gpu::Context& ctx)
    : pipeline(gpu::createGraphicsPipeline(ctx, {.vertexShader = "ground.vert",
                                                 .fragmentShader = "ground.frag",
                                                 .pushSize = sizeof(shader::GroundParams),
                                                 .colorFormats = {kHdrFormat},
                                                 .depthFormat = kDepthFormat,
                                                 .depthTest = true,
                                                 .depthWrite = true})) {}

void GroundPass::declare(FrameGraph& graph, ResourceRef colorRef, const gpu::Image& color, ResourceRef depthRef,
                         const gpu::Image& depth, const gpu::Buffer& frameUniforms,
                         const shader::GroundParams& params) const {
  graph.pass("ground", {{colorRef, Use::ColorReadWrite}, {depthRef, Use::DepthWrite}},
             [this, &color, &depth, &frameUniforms, params](PassContext& pc) {
               const auto& cmd = pc.cmd;
               auto colorTarget = attachment(color, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
               auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                                             vk::ClearValue{.depthStencil = {1.0f, 0}});
               cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, color.extent},
                                                    .layerCount = 1,
                                                    .colorAttachmentCount = 1,
                                                    .pColorAttachments = &colorTarget,
                                                    .pDepthAttachment = &depthTarget});
               gpu::bindPipeline(cmd, pipeline, params);
               gpu::DescriptorWrites().uniformBuffer(0, frameUniforms).bind(cmd, pipeline, pc.descriptors);
               setViewport(cmd, color.extent);
               cmd.draw(6, 1, 0, 0);
               cmd.endRendering();
             });
}

WaterSurfacePass::WaterSurfacePass(const gpu::Context& ctx)
    : pipeline(gpu::createGraphicsPipeline(ctx, {.vertexShader = "water_surface.vert",
                                                 .fragmentShader = "water_surface.frag",
                                                 .pushSize = sizeof(shader::WaterSurfaceParams),
                                                 .colorFormats = {kHdrFormat},
                                                 .depthFormat = kDepthFormat,
                                                 .depthTest = true,
                                                 .depthWrite = true})) {}

void WaterSurfacePass::declare(FrameGraph& graph, ResourceRef colorRef, const gpu::Image& color, ResourceRef depthRef,
                               const gpu::Image& depth, std::vector<ResourceRef> stateRefs,
                               std::function<const gpu::Buffer&()> state, ResourceRef skyRef, const gpu::Image& sky,
                               vk::Sampler sampler, const gpu::Buffer& frameUniforms, const gpu::Buffer& indices,
                               uint32_t indexCount, const shader::WaterSurfaceParams& params) const {
  std::vector<std::pair<ResourceRef, Use>> uses{
      {skyRef, Use::FragmentSample}, {colorRef, Use::ColorReadWrite}, {depthRef, Use::DepthReadWrite}};
  for (ResourceRef r : stateRefs) uses.push_back({r, Use::VertexStorageRead});
  graph.pass("water", std::move(uses),
             [this, &color, &depth, state, &sky, sampler, &frameUniforms, &indices, indexCount, params](PassContext& pc) {
               const auto& cmd = pc.cmd;
               auto colorTarget = attachment(color, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
               auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
               cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, color.extent},
                                                    .layerCount = 1,
                                                    .colorAttachmentCount = 1,
                                                    .pColorAttachments = &colorTarget,
                                                    .pDepthAttachment = &depthTarget});
               gpu::bindPipeline(cmd, pipeline, params);
               gpu::DescriptorWrites()
                   .uniformBuffer(0, frameUniforms)
                   .sampledImage(1, sky, sampler)
                   .storageBuffer(2, state())
                   .bind(cmd, pipeline, pc.descriptors);
               setViewport(cmd, color.extent);
               cmd.bindIndexBuffer(indices.handle(), 0, vk::IndexType::eUint32);
               cmd.drawIndexed(indexCount, 1, 0, 0, 0);
               cmd.endRendering();
             });
}

TonemapPass::TonemapPass(const gpu::Context& ctx)
    : pipeline(gpu::createComputePipeline(ctx, "tonemap.comp", sizeof(shader::TonemapParams))) {}

void TonemapPass::declare(FrameGraph& graph, ResourceRef hdrRef, const gpu::Image& hdr, ResourceRef ldrRef,
                          const gpu::Image& ldr, float exposure) const {
  shader::TonemapParams params{.size = {hdr.extent.width, hdr.extent.height}, .exposure = exposure, .pad = 0.0f};
  graph.pass("tonemap", {{hdrRef, Use::ComputeRead}, {ldrRef, Use::ComputeWrite}},
             [this, &hdr, &ldr, params](PassContext& pc) {
               const auto& cmd = pc.cmd;
               gpu::bindPipeline(cmd, pipeline, params);
               gpu::DescriptorWrites().storageImage(0, hdr).storageImage(1, ldr).bind(cmd, pipeline, pc.descriptors);
               gpu::dispatchCovering(cmd, pipeline, params.size.x, params.size.y);
             });
}

void declareReadback(FrameGraph& graph, const std::string& name, ResourceRef imageRef, const gpu::Image& image,
                     ResourceRef bufferRef, const gpu::Buffer& buffer) {
  graph.pass(name, {{imageRef, Use::TransferRead}, {bufferRef, Use::TransferWrite}},
             [&image, &buffer](PassContext& pc) {
               const auto& cmd = pc.cmd;
               vk::BufferImageCopy region{
                   .bufferOffset = 0,
                   .bufferRowLength = 0,
                   .bufferImageHeight = 0,
                   .imageSubresource = {image.aspect, 0, 0, 1},
                   .imageOffset = {0, 0, 0},
                   .imageExtent = {image.extent.width, image.extent.height, 1},
               };
               cmd.copyImageToBuffer(image.handle(), vk::ImageLayout::eTransferSrcOptimal, buffer.handle(), region);
             });
}

}  // namespace tp::render
