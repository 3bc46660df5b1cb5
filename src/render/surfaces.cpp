#include "render/surfaces.hpp"

#include <array>
#include <vector>

#include "shading/frame_uniforms.hpp"
#include "shading/glass_caustic.hpp"
#include "shading/glossy_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/specialization.h"

namespace tp::render {

Samplers::Samplers(const gpu::Context& ctx)
    : equirect(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eLinear,
                                                   .minFilter = vk::Filter::eLinear,
                                                   .mipmapMode = vk::SamplerMipmapMode::eLinear,
                                                   .addressModeU = vk::SamplerAddressMode::eRepeat,
                                                   .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                   .addressModeW = vk::SamplerAddressMode::eClampToEdge,
                                                   .maxLod = VK_LOD_CLAMP_NONE}),
      nearest(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest,
                                                  .minFilter = vk::Filter::eNearest,
                                                  .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                  .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                  .addressModeW = vk::SamplerAddressMode::eClampToEdge}),
      clamp(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eLinear,
                                                .minFilter = vk::Filter::eLinear,
                                                .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                .addressModeW = vk::SamplerAddressMode::eClampToEdge}) {}

void setViewport(const vk::raii::CommandBuffer& cmd, vk::Extent2D extent) {
  cmd.setViewport(0, vk::Viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f});
  cmd.setScissor(0, vk::Rect2D{{0, 0}, extent});
}

vk::RenderingAttachmentInfo attachment(const gpu::Image& image, vk::ImageLayout layout, vk::AttachmentLoadOp load,
                                       vk::ClearValue clear) {
  return vk::RenderingAttachmentInfo{.imageView = *image.view,
                                     .imageLayout = layout,
                                     .loadOp = load,
                                     .storeOp = vk::AttachmentStoreOp::eStore,
                                     .clearValue = clear};
}

void attachSurfaces(PassBuilder& pass, const SurfaceTargets& t, bool first) {
  pass.attach(t.depth, first ? Use::DepthWrite : Use::DepthReadWrite);
  pass.attach(t.color, first ? Use::ColorWrite : Use::ColorReadWrite);
  if (!t.gbuffer()) return;
  for (const GraphImage& g : {t.normal, t.ambient}) pass.attach(g, first ? Use::ColorWrite : Use::ColorReadWrite);
}

void drawSurfaces(const vk::raii::CommandBuffer& cmd, const SurfaceTargets& t, bool first,
                  const std::function<void()>& draw) {
  const auto load = first ? vk::AttachmentLoadOp::eClear : vk::AttachmentLoadOp::eLoad;
  auto colorTarget = [&](const GraphImage& target) {
    return attachment(*target.image, vk::ImageLayout::eColorAttachmentOptimal, load,
                      vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}});
  };
  std::vector<vk::RenderingAttachmentInfo> colorTargets{colorTarget(t.color)};
  if (t.gbuffer()) colorTargets.insert(colorTargets.end(), {colorTarget(t.normal), colorTarget(t.ambient)});
  auto depthTarget = attachment(*t.depth.image, vk::ImageLayout::eDepthAttachmentOptimal, load,
                                vk::ClearValue{.depthStencil = {1.0f, 0}});
  renderTo(cmd, colorTargets, &depthTarget, t.color.image->extent, draw);
}

void drawOver(const vk::raii::CommandBuffer& cmd, const gpu::Image& color, const gpu::Image& depth,
              const std::function<void()>& draw, const gpu::Image* second) {
  std::vector<vk::RenderingAttachmentInfo> colorTargets{
      attachment(color, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eLoad)};
  if (second) {
    colorTargets.push_back(attachment(*second, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eLoad));
  }
  auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
  renderTo(cmd, colorTargets, &depthTarget, color.extent, draw);
}

void renderTo(const vk::raii::CommandBuffer& cmd, std::span<const vk::RenderingAttachmentInfo> colors,
              const vk::RenderingAttachmentInfo* depth, vk::Extent2D extent, const std::function<void()>& draw) {
  cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent},
                                       .layerCount = 1,
                                       .colorAttachmentCount = uint32_t(colors.size()),
                                       .pColorAttachments = colors.data(),
                                       .pDepthAttachment = depth});
  setViewport(cmd, extent);
  draw();
  cmd.endRendering();
}

std::string fragmentVariant(const std::string& fragmentShader, FragmentNeeds needs) {
  const size_t stage = fragmentShader.rfind('.');
  std::string name = fragmentShader.substr(0, stage);
  if (!needs.gbuffer) name += ".color_only";
  if (!needs.shadows) name += ".no_shadows";
  if (needs.scattering) name += ".scattering";
  if (needs.glass) name += ".glass";
  if (needs.clearAmbient) name += ".clear_ambient";
  return name + fragmentShader.substr(stage);
}

FragmentNeeds surfaceNeeds(const scene::Scene& scene, bool gbuffer, bool skipping) {
  return {.gbuffer = gbuffer,
          .shadows = castsShadows(scene),
          .scattering = hasWaterScattering(scene),
          .sphereShadows = !skipping || spheresCastShadows(scene),
          .boxShadows = !skipping || boxesCastShadows(scene),
          .glassShadows = !skipping || glassCastsShadows(scene),
          .glossy = !skipping || hasGlossySurface(scene),
          .brickWalls = !skipping || hasBrickWalls(scene),
          .tiles = !skipping || hasTiledSurface(scene)};
}

gpu::Specialization fragmentSpecialization(FragmentNeeds needs) {
  return gpu::Specialization()
      .set(TP_SPEC_SPHERE_SHADOWS, uint32_t(needs.sphereShadows))
      .set(TP_SPEC_BOX_SHADOWS, uint32_t(needs.boxShadows))
      .set(TP_SPEC_GLASS_SHADOWS, uint32_t(needs.glassShadows))
      .set(TP_SPEC_GLOSSY, uint32_t(needs.glossy))
      .set(TP_SPEC_BRICK_WALLS, uint32_t(needs.brickWalls))
      .set(TP_SPEC_TILES, uint32_t(needs.tiles));
}

gpu::GraphicsPipelineDesc opaquePipeline(const std::string& vertexShader, const std::string& fragmentShader,
                                         uint32_t pushSize, FragmentNeeds needs) {
  return {
      .vertexShader = vertexShader,
      .fragmentShader = fragmentVariant(fragmentShader, needs),
      .pushSize = pushSize,
      .colorFormats = needs.gbuffer ? std::vector{kHdrFormat, kGbufferFormat, kGbufferFormat} : std::vector{kHdrFormat},
      .depthFormat = kDepthFormat,
      .depthTest = true,
      .depthWrite = true,
      .fragmentSpecialization = fragmentSpecialization(needs)};
}

}  // namespace tp::render
