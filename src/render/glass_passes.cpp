#include "render/glass_passes.hpp"

#include <array>

#include "gpu/commands.hpp"
#include "gpu/descriptors.hpp"
#include "render/objects_model.hpp"

namespace tp::render {
namespace {

// sphere.vert tessellates each sphere (GlassSphereParams begins with its
// SphereParams); the back faces with the front ones culled, and the reverse.
gpu::GraphicsPipelineDesc glassSide(const char* fragmentShader, vk::Format colorFormat, vk::CullModeFlags cull) {
  return {.vertexShader = "sphere.vert",
          .fragmentShader = fragmentShader,
          .pushSize = sizeof(shader::GlassSphereParams),
          .colorFormats = {colorFormat},
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true,
          .cullMode = cull};
}

void drawSpheres(const vk::raii::CommandBuffer& cmd, const gpu::Pipeline& pipeline,
                 const std::vector<shader::GlassSphereParams>& spheres) {
  for (const auto& sphere : spheres) {
    gpu::bindPipeline(cmd, pipeline, sphere);
    gpu::draw(cmd, sphereVertexCount(sphere.tessellation));
  }
}

}  // namespace

GlassPasses::GlassPasses(const gpu::Context& ctx)
    : back(gpu::createGraphicsPipeline(ctx, glassSide("glass_back.frag", kGlassBackFormat, vk::CullModeFlagBits::eFront))),
      front(gpu::createGraphicsPipeline(ctx, glassSide("glass.frag", kHdrFormat, vk::CullModeFlagBits::eBack))) {}

void GlassPasses::declare(FrameGraph& graph, const GlassTargets& glass, const SurfaceTargets& frame,
                          const MediumDraw& medium, ResourceRef skyRef, const gpu::Image& sky, vk::Sampler skySampler,
                          vk::Sampler nearest, const gpu::Buffer& frameUniforms,
                          const std::vector<shader::GlassSphereParams>* spheres) const {
  auto inView = [spheres] { return !spheres->empty(); };
  // The nearest back face of any glass sphere, alone: the opaque surfaces do
  // not hide it (a refracted ray may leave behind one of them).
  graph.pass("glass back faces", {{glass.backFaces.ref, Use::ColorWrite}, {glass.depth.ref, Use::DepthWrite}},
             [this, glass, &frameUniforms, spheres](PassContext& pc) {
               const auto& cmd = pc.cmd;
               auto target = attachment(*glass.backFaces.image, vk::ImageLayout::eColorAttachmentOptimal,
                                        vk::AttachmentLoadOp::eClear,
                                        vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}});
               auto depthTarget = attachment(*glass.depth.image, vk::ImageLayout::eDepthAttachmentOptimal,
                                             vk::AttachmentLoadOp::eClear, vk::ClearValue{.depthStencil = {1.0f, 0}});
               const vk::Extent2D extent = glass.backFaces.image->extent;
               cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent},
                                                    .layerCount = 1,
                                                    .colorAttachmentCount = 1,
                                                    .pColorAttachments = &target,
                                                    .pDepthAttachment = &depthTarget});
               setViewport(cmd, extent);
               cmd.bindPipeline(back.bindPoint, *back.pipeline);
               gpu::DescriptorWrites().uniformBuffer(0, frameUniforms).bind(cmd, back, pc.descriptors);
               drawSpheres(cmd, back, *spheres);
               cmd.endRendering();
             },
             {.cached = false, .runIf = inView});
  // The front faces over the frame, depth tested against what is drawn.
  graph.pass("glass",
             {{glass.backFaces.ref, Use::FragmentSample},
              {skyRef, Use::FragmentSample},
              {medium.ref, Use::FragmentUniformRead},
              {frame.color.ref, Use::ColorReadWrite},
              {frame.depth.ref, Use::DepthReadWrite}},
             [this, glass, frame, medium, &sky, skySampler, nearest, &frameUniforms, spheres](PassContext& pc) {
               drawOver(pc.cmd, *frame.color.image, *frame.depth.image, [&] {
                 pc.cmd.bindPipeline(front.bindPoint, *front.pipeline);
                 gpu::DescriptorWrites()
                     .uniformBuffer(0, frameUniforms)
                     .sampledImage(1, sky, skySampler)
                     .sampledImage(2, *glass.backFaces.image, nearest)
                     .uniformBuffer(3, *medium.buffer)
                     .bind(pc.cmd, front, pc.descriptors);
                 drawSpheres(pc.cmd, front, *spheres);
               });
             },
             {.cached = false, .runIf = inView});
}

}  // namespace tp::render
