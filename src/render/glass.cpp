#include "render/glass.hpp"

#include <array>

#include "gpu/commands.hpp"
#include "gpu/descriptors.hpp"
#include "render/pass_kinds.hpp"
#include "shading/objects_model.hpp"

namespace tp::render {
namespace {

// sphere.vert tessellates each sphere (GlassSphereParams begins with its
// SphereParams); the back faces with the front ones culled, and the reverse.
// The fragment shader's variant and specialization as `needs` says.
gpu::GraphicsPipelineDesc glassSide(const std::string& fragmentShader, vk::Format colorFormat, vk::CullModeFlags cull,
                                    FragmentNeeds needs = {}) {
  return {.vertexShader = "sphere.vert",
          .fragmentShader = fragmentVariant(fragmentShader, needs),
          .pushSize = sizeof(shader::GlassSphereParams),
          .colorFormats = {colorFormat},
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true,
          .cullMode = cull,
          .fragmentSpecialization = fragmentSpecialization(needs)};
}

// Glass writes colour alone, so it has no colour-only variants, and its
// rays meet no other glass.
FragmentNeeds glassNeeds(FragmentNeeds surfaces) {
  FragmentNeeds needs = surfaces;
  needs.gbuffer = true;
  needs.glass = false;
  return needs;
}

void drawSpheres(const vk::raii::CommandBuffer& cmd, const gpu::Pipeline& pipeline,
                 const std::vector<shader::GlassSphereParams>& spheres) {
  for (const auto& sphere : spheres) {
    gpu::bindPipeline(cmd, pipeline, sphere);
    gpu::draw(cmd, sphereVertexCount(sphere.tessellation));
  }
}

// The glass boxes' front faces: box.vert (GlassBoxParams begins with its
// BoxParams), glass.frag's box variant (TP_GLASS_BOX), which follows the
// exact path through the box and needs no back faces.
gpu::GraphicsPipelineDesc glassBoxFront(FragmentNeeds needs) {
  gpu::GraphicsPipelineDesc desc = glassSide("glass.frag", kHdrFormat, vk::CullModeFlagBits::eBack, needs);
  desc.vertexShader = "box.vert";
  desc.fragmentShader.insert(desc.fragmentShader.rfind('.'), ".box");
  desc.pushSize = sizeof(shader::GlassBoxParams);
  return desc;
}

}  // namespace

Glass::Glass(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D frame, FragmentNeeds needs, const PoolDraw& pool,
             const scene::Scene& scene)
    : pool_(pool) {
  // Only the pipelines the scene's glass draws with: each takes time to make.
  if (scene::hasGlassSpheres(scene)) {
    back_.emplace(
        gpu::createGraphicsPipeline(ctx, glassSide("glass_back.frag", kGlassBackFormat, vk::CullModeFlagBits::eFront)));
    front_.emplace(gpu::createGraphicsPipeline(
        ctx, glassSide("glass.frag", kHdrFormat, vk::CullModeFlagBits::eBack, glassNeeds(needs))));
  }
  if (scene::hasGlassBoxes(scene))
    boxFront_.emplace(gpu::createGraphicsPipeline(ctx, glassBoxFront(glassNeeds(needs))));
  backFaces_ = gpu::createImage2D(ctx, frame, kGlassBackFormat,
                                  vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled,
                                  "glass back faces");
  depth_ = gpu::createImage2D(ctx, frame, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                              "glass back-face depth");
  backFacesRef_ = graph.image("glass back faces", backFaces_);
  depthRef_ = graph.image("glass depth", depth_);
}

void Glass::declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in,
                    const std::vector<shader::GlassSphereParams>& spheres,
                    const std::vector<shader::GlassBoxParams>& boxes) const {
  auto inView = [&spheres, &boxes] { return !spheres.empty() || !boxes.empty(); };
  // The nearest back face of any glass sphere, alone: the opaque surfaces do
  // not hide it (a refracted ray may leave behind one of them).
  graph.pass(passes::kGlassBackFaces,
             [this, in, &spheres](PassBuilder& pass) {
               const gpu::Image& backFaces = pass.attach(backFacesRef_, Use::ColorWrite);
               const gpu::Image& depth = pass.attach(depthRef_, Use::DepthWrite);
               Bindings& set = pass.bindings().uniformBuffer(0, in.uniforms, Use::HostData);
               return [this, &backFaces, &depth, &set, &spheres](PassContext& pc) {
                 const auto& cmd = pc.cmd;
                 auto target =
                     attachment(backFaces, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                                vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}});
                 auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal,
                                               vk::AttachmentLoadOp::eClear, vk::ClearValue{.depthStencil = {1.0f, 0}});
                 renderTo(cmd, std::span(&target, 1), &depthTarget, backFaces.extent, [&] {
                   cmd.bindPipeline(back_->bindPoint, *back_->pipeline);
                   set.bind(cmd, *back_, pc.descriptors);
                   drawSpheres(cmd, *back_, spheres);
                 });
               };
             },
             // Glass boxes need no back faces.
             {.cached = false, .runIf = [&spheres] { return !spheres.empty(); }});
  // The front faces over the frame, depth tested against what is drawn.
  graph.pass(passes::kGlass,
             [this, frame, in, &spheres, &boxes](PassBuilder& pass) {
               const gpu::Image& color = pass.attach(frame.color, Use::ColorReadWrite);
               const gpu::Image& depth = pass.attach(frame.depth, Use::DepthReadWrite);
               Bindings& set = pass.bindings()
                                   .uniformBuffer(0, in.uniforms, Use::HostData)
                                   .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData)
                                   .sampledImage(1, in.sky, in.equirect, Use::FragmentSample)
                                   .sampledImage(2, backFacesRef_, in.nearest, Use::FragmentSample)
                                   .constantBuffer(3, *pool_.uniforms)
                                   .constantBuffer(4, *pool_.objects)
                                   .uniformBuffer(5, in.medium, Use::FragmentUniformRead)
                                   .sampledImage(6, pool_.caustics, in.clamp, Use::FragmentSample)
                                   .sampledImage(7, in.glossy, in.equirect, Use::FragmentSample)
                                   .constantStorageBuffer(8, *pool_.floorVertices);
               return [this, &color, &depth, &set, &spheres, &boxes](PassContext& pc) {
                 drawOver(pc.cmd, color, depth, [&] {
                   if (!spheres.empty()) {
                     pc.cmd.bindPipeline(front_->bindPoint, *front_->pipeline);
                     set.bind(pc.cmd, *front_, pc.descriptors);
                     drawSpheres(pc.cmd, *front_, spheres);
                   }
                   if (boxFront_ && !boxes.empty()) {
                     pc.cmd.bindPipeline(boxFront_->bindPoint, *boxFront_->pipeline);
                     set.bind(pc.cmd, *boxFront_, pc.descriptors);
                     for (const auto& box : boxes) {
                       gpu::bindPipeline(pc.cmd, *boxFront_, box);
                       gpu::draw(pc.cmd, kBoxVertices);
                     }
                   }
                 });
               };
             },
             {.cached = false, .runIf = inView});
}

}  // namespace tp::render
