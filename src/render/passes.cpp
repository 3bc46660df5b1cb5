#include "render/passes.hpp"

#include "gpu/commands.hpp"
#include "gpu/descriptors.hpp"
#include "render/objects_model.hpp"

#include <array>
#include <functional>
#include <limits>

namespace tp::render {

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

// Draws over what the colour and depth targets already hold (both loaded and
// stored): the framing of the water pass, which has no G-buffer targets.
void drawOver(const vk::raii::CommandBuffer& cmd, const gpu::Image& color, const gpu::Image& depth,
              const std::function<void()>& draw) {
  auto colorTarget = attachment(color, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
  auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal, vk::AttachmentLoadOp::eLoad);
  cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, color.extent},
                                       .layerCount = 1,
                                       .colorAttachmentCount = 1,
                                       .pColorAttachments = &colorTarget,
                                       .pDepthAttachment = &depthTarget});
  setViewport(cmd, color.extent);
  draw();
  cmd.endRendering();
}

namespace {

// Renders over the opaque surfaces' targets. The first surface pass
// (`first`) clears depth and the G-buffer (zero ambient: AO takes nothing from
// pixels no surface covers); later ones load them.
void drawSurfaces(const vk::raii::CommandBuffer& cmd, const SurfaceTargets& t, bool first,
                  const std::function<void()>& draw) {
  const auto load = first ? vk::AttachmentLoadOp::eClear : vk::AttachmentLoadOp::eLoad;
  auto gbufferTarget = [&](const Target& target) {
    return attachment(*target.image, vk::ImageLayout::eColorAttachmentOptimal, load,
                      vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}});
  };
  std::vector<vk::RenderingAttachmentInfo> colorTargets{
      attachment(*t.color.image, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eLoad)};
  if (t.gbuffer()) colorTargets.insert(colorTargets.end(), {gbufferTarget(t.normal), gbufferTarget(t.ambient)});
  auto depthTarget = attachment(*t.depth.image, vk::ImageLayout::eDepthAttachmentOptimal, load,
                                vk::ClearValue{.depthStencil = {1.0f, 0}});
  const vk::Extent2D extent = t.color.image->extent;
  cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent},
                                       .layerCount = 1,
                                       .colorAttachmentCount = uint32_t(colorTargets.size()),
                                       .pColorAttachments = colorTargets.data(),
                                       .pDepthAttachment = &depthTarget});
  setViewport(cmd, extent);
  draw();
  cmd.endRendering();
}

// The frame-graph uses of a surface pass: colour drawn over, depth and the
// G-buffer cleared by the first and drawn over by the rest.
std::vector<std::pair<ResourceRef, Use>> surfaceUses(const SurfaceTargets& t, bool first) {
  std::vector<std::pair<ResourceRef, Use>> uses{{t.color.ref, Use::ColorReadWrite},
                                                {t.depth.ref, first ? Use::DepthWrite : Use::DepthReadWrite}};
  if (!t.gbuffer()) return uses;
  for (const Target& g : {t.normal, t.ambient}) uses.push_back({g.ref, first ? Use::ColorWrite : Use::ColorReadWrite});
  return uses;
}

constexpr uint32_t kGroundVertices = 24;  // ground.vert: four quads around the pool's hole
constexpr uint32_t kWallVertices = 24;    // pool_walls.vert: four quads

// `medium`: none for the AOV pass, whose fragment shader reads neither it nor the caustics.
void drawPool(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& walls,
              const gpu::Pipeline& floor, const gpu::Buffer& frameUniforms, const PoolDraw& pool,
              const gpu::Buffer* medium) {
  cmd.bindPipeline(walls.bindPoint, *walls.pipeline);
  gpu::DescriptorWrites wallWrites;
  wallWrites.uniformBuffer(0, frameUniforms).uniformBuffer(1, *pool.uniforms);
  if (medium) wallWrites.uniformBuffer(3, *medium).sampledImage(4, *pool.glossy.image, pool.glossy.sampler);
  wallWrites.bind(cmd, walls, arena);
  gpu::draw(cmd, kWallVertices);
  gpu::bindPipeline(cmd, floor, glm::uvec4(pool.floorGrid, 0u, 0u, 0u));
  gpu::DescriptorWrites writes;
  writes.uniformBuffer(0, frameUniforms).uniformBuffer(1, *pool.uniforms);
  if (medium) writes.sampledImage(2, *pool.caustics, pool.causticsSampler).uniformBuffer(3, *medium);
  writes.bind(cmd, floor, arena);
  cmd.bindIndexBuffer(pool.floorIndices->handle(), 0, vk::IndexType::eUint32);
  gpu::drawIndexed(cmd, pool.floorIndexCount);
}

// A pipeline of an opaque surface: colour, the two G-buffer targets (or,
// without them, the fragment shader's colour-only variant), depth.
gpu::GraphicsPipelineDesc opaque(const std::string& vertexShader, const std::string& fragmentShader, uint32_t pushSize,
                                 bool gbuffer) {
  const std::string colorOnly = fragmentShader.substr(0, fragmentShader.rfind('.')) + ".color_only.frag";
  return {.vertexShader = vertexShader,
          .fragmentShader = gbuffer ? fragmentShader : colorOnly,
          .pushSize = pushSize,
          .colorFormats = gbuffer ? std::vector{kHdrFormat, kGbufferFormat, kGbufferFormat} : std::vector{kHdrFormat},
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true};
}

}  // namespace

// `medium`: none for the AOV pass.
// `glossy`: the spheres' environment (none for the AOV pass).
static void drawObjects(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& spheres,
                        const gpu::Pipeline& boxes, const gpu::Buffer& frameUniforms, const gpu::Buffer* medium,
                        const GlossyDraw* glossy, const std::vector<shader::SphereParams>& sphereDraws,
                        const std::vector<shader::BoxParams>& boxDraws) {
  auto bindShared = [&](const gpu::Pipeline& pipeline) {
    cmd.bindPipeline(pipeline.bindPoint, *pipeline.pipeline);
    gpu::DescriptorWrites writes;
    writes.uniformBuffer(0, frameUniforms);
    if (medium) writes.uniformBuffer(1, *medium);
    if (glossy && gpu::hasBinding(pipeline, 2)) writes.sampledImage(2, *glossy->image, glossy->sampler);
    writes.bind(cmd, pipeline, arena);
  };
  if (!sphereDraws.empty()) {
    bindShared(spheres);
    for (const auto& sphere : sphereDraws) {
      gpu::bindPipeline(cmd, spheres, sphere);
      gpu::draw(cmd, sphereVertexCount(sphere.tessellation));
    }
  }
  if (!boxDraws.empty()) {
    bindShared(boxes);
    for (const auto& box : boxDraws) {
      gpu::bindPipeline(cmd, boxes, box);
      gpu::draw(cmd, kBoxVertices);
    }
  }
}

ObjectPass::ObjectPass(const gpu::Context& ctx, bool gbuffer)
    : spherePipeline(
          gpu::createGraphicsPipeline(ctx, opaque("sphere.vert", "sphere.frag", sizeof(shader::SphereParams), gbuffer))),
      boxPipeline(gpu::createGraphicsPipeline(ctx, opaque("box.vert", "box.frag", sizeof(shader::BoxParams), gbuffer))) {}

void ObjectPass::declare(FrameGraph& graph, const SurfaceTargets& targets, const gpu::Buffer& frameUniforms,
                         const MediumDraw& medium, const GlossyDraw& glossy,
                         const std::vector<shader::SphereParams>* spheres,
                         const std::vector<shader::BoxParams>* boxes) const {
  auto uses = surfaceUses(targets, false);
  uses.push_back({medium.ref, Use::FragmentUniformRead});
  uses.push_back({glossy.ref, Use::FragmentSample});
  graph.pass("objects", std::move(uses), [this, targets, &frameUniforms, medium, glossy, spheres, boxes](PassContext& pc) {
    drawSurfaces(pc.cmd, targets, false, [&] {
      drawObjects(pc.cmd, pc.descriptors, spherePipeline, boxPipeline, frameUniforms, medium.buffer, &glossy, *spheres,
                  *boxes);
    });
  }, {.cached = false, .runIf = [spheres, boxes] { return !spheres->empty() || !boxes->empty(); }});
}

PoolPass::PoolPass(const gpu::Context& ctx, bool gbuffer)
    : walls(gpu::createGraphicsPipeline(ctx, opaque("pool_walls.vert", "pool_walls.frag", 0, gbuffer))),
      floor(gpu::createGraphicsPipeline(ctx, opaque("pool_floor.vert", "pool_floor.frag", sizeof(glm::uvec4), gbuffer))) {}

void PoolPass::declare(FrameGraph& graph, const SurfaceTargets& targets, const gpu::Buffer& frameUniforms,
                       const PoolDraw& pool, const MediumDraw& medium) const {
  auto uses = surfaceUses(targets, false);
  uses.push_back({pool.causticsRef, Use::FragmentSample});
  uses.push_back({medium.ref, Use::FragmentUniformRead});
  uses.push_back({pool.glossy.ref, Use::FragmentSample});
  graph.pass("pool", std::move(uses), [this, targets, &frameUniforms, pool, medium](PassContext& pc) {
    drawSurfaces(pc.cmd, targets, false,
                 [&] { drawPool(pc.cmd, pc.descriptors, walls, floor, frameUniforms, pool, medium.buffer); });
  });
}

SkyPass::SkyPass(const gpu::Context& ctx)
    : pipeline(gpu::createComputePipeline(ctx, "sky.comp", sizeof(shader::SkyParams))) {}

void SkyPass::declare(FrameGraph& graph, ResourceRef skyRef, const gpu::Image& sky,
                      const shader::SkyParams& params) const {
  graph.pass("sky", {{skyRef, Use::ComputeWrite}}, [this, &sky, params](PassContext& pc) {
    const auto& cmd = pc.cmd;
    gpu::bindPipeline(cmd, pipeline, params);
    gpu::DescriptorWrites().storageImage(0, sky).bind(cmd, pipeline, pc.descriptors);
    gpu::dispatchCovering(cmd, pipeline, params.counts.x, params.counts.x / 2);
  }, {.cached = true, .runIf = {}});
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
               gpu::draw(cmd, 3);
               cmd.endRendering();
             });
}

GroundPass::GroundPass(const gpu::Context& ctx, bool gbuffer)
    : pipeline(
          gpu::createGraphicsPipeline(ctx, opaque("ground.vert", "ground.frag", sizeof(shader::GroundParams), gbuffer))) {}

void GroundPass::declare(FrameGraph& graph, const SurfaceTargets& targets, const gpu::Buffer& frameUniforms,
                         const shader::GroundParams& params) const {
  graph.pass("ground", surfaceUses(targets, true), [this, targets, &frameUniforms, params](PassContext& pc) {
    drawSurfaces(pc.cmd, targets, true, [&] {
      gpu::bindPipeline(pc.cmd, pipeline, params);
      gpu::DescriptorWrites().uniformBuffer(0, frameUniforms).bind(pc.cmd, pipeline, pc.descriptors);
      gpu::draw(pc.cmd, kGroundVertices);
    });
  });
}

namespace {
// One side of the water mesh: its front faces (seen from above) shaded by the
// refraction mode's shader, its back faces (seen from below) by the shader
// both modes share, the other side culled.
gpu::GraphicsPipelineDesc waterSide(const char* fragmentShader, vk::CullModeFlags cull) {
  return {.vertexShader = "water_surface.vert",
          .fragmentShader = fragmentShader,
          .pushSize = sizeof(shader::WaterSurfaceParams),
          .colorFormats = {kHdrFormat},
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true,
          .topology = vk::PrimitiveTopology::eTriangleStrip,
          .cullMode = cull};
}
}  // namespace

WaterSurfacePass::WaterSurfacePass(const gpu::Context& ctx, bool apparentDepth)
    : above(gpu::createGraphicsPipeline(
          ctx, waterSide(apparentDepth ? "water_surface_apparent.frag" : "water_surface.frag", vk::CullModeFlagBits::eBack))),
      below(gpu::createGraphicsPipeline(ctx, waterSide("water_surface_below.frag", vk::CullModeFlagBits::eFront))) {}

static void drawWater(const vk::raii::CommandBuffer& cmd, const WaterDraw& water) {
  cmd.bindIndexBuffer(water.indices->handle(), 0, vk::IndexType::eUint32);
  gpu::drawIndexed(cmd, water.indexCount);
}

void WaterSurfacePass::declare(FrameGraph& graph, ResourceRef colorRef, const gpu::Image& color, ResourceRef depthRef,
                               const gpu::Image& depth, const WaterDraw& water, const PoolDraw& pool,
                               ResourceRef skyRef, const gpu::Image& sky, vk::Sampler sampler,
                               const gpu::Buffer& frameUniforms, std::optional<Underwater> underwater) const {
  std::vector<std::pair<ResourceRef, Use>> uses{
      {skyRef, Use::FragmentSample}, {colorRef, Use::ColorReadWrite}, {depthRef, Use::DepthReadWrite}};
  for (ResourceRef r : water.stateRefs) uses.push_back({r, Use::VertexStorageRead});
  if (underwater) uses.push_back({underwater->ref, Use::FragmentSample});
  uses.push_back({pool.causticsRef, Use::FragmentSample});  // the floor the refracted (or, from below, reflected) rays meet
  uses.push_back({pool.glossy.ref, Use::FragmentSample});    // the glossy walls and spheres they meet
  graph.pass("water", std::move(uses),
             [this, &color, &depth, water, pool, &sky, sampler, &frameUniforms, underwater](PassContext& pc) {
    const auto& cmd = pc.cmd;
    drawOver(cmd, color, depth, [&] {
      for (const gpu::Pipeline* side : {&above, &below}) {
        gpu::bindPipeline(cmd, *side, water.params);
        gpu::DescriptorWrites writes;
        writes.uniformBuffer(0, frameUniforms)
            .sampledImage(1, sky, sampler)
            .storageBuffer(2, water.state())
            .uniformBuffer(3, *pool.uniforms)
            .uniformBuffer(4, *pool.objects);
        if (underwater && gpu::hasBinding(*side, 5)) writes.sampledImage(5, *underwater->image, underwater->sampler);
        writes.sampledImage(6, *pool.caustics, pool.causticsSampler);
        if (gpu::hasBinding(*side, 7)) writes.sampledImage(7, *pool.glossy.image, pool.glossy.sampler);
        writes.bind(cmd, *side, pc.descriptors);
        drawWater(cmd, water);
      }
    });
  });
}

CausticsPass::CausticsPass(const gpu::Context& ctx)
    : pipeline(gpu::createGraphicsPipeline(ctx, {.vertexShader = "caustics.vert",
                                                 .fragmentShader = "caustics.frag",
                                                 .pushSize = sizeof(shader::WaterSurfaceParams),
                                                 .colorFormats = {kCausticsFormat},
                                                 .topology = vk::PrimitiveTopology::eTriangleStrip,
                                                 .additive = true})) {}

void CausticsPass::declare(FrameGraph& graph, const WaterDraw& water, const PoolDraw& pool,
                           const gpu::Buffer& frameUniforms, ResourceRef uniformsRef) const {
  std::vector<std::pair<ResourceRef, Use>> uses{{pool.causticsRef, Use::ColorWrite}, {uniformsRef, Use::HostData}};
  for (ResourceRef r : water.stateRefs) uses.push_back({r, Use::VertexStorageRead});
  graph.pass("caustics", std::move(uses), [this, water, pool, &frameUniforms](PassContext& pc) {
    const auto& cmd = pc.cmd;
    const gpu::Image& target = *pool.caustics;
    auto colorTarget = attachment(target, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                                  vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}});
    cmd.beginRendering(vk::RenderingInfo{
        .renderArea = {{0, 0}, target.extent}, .layerCount = 1, .colorAttachmentCount = 1, .pColorAttachments = &colorTarget});
    setViewport(cmd, target.extent);
    gpu::bindPipeline(cmd, pipeline, water.params);
    gpu::DescriptorWrites()
        .uniformBuffer(0, frameUniforms)
        .storageBuffer(2, water.state())
        .uniformBuffer(3, *pool.uniforms)
        .bind(cmd, pipeline, pc.descriptors);
    drawWater(cmd, water);
    cmd.endRendering();
  }, {.cached = true, .runIf = {}});
}

namespace {
gpu::GraphicsPipelineDesc aovPipeline(const char* vertexShader, uint32_t pushSize) {
  return {.vertexShader = vertexShader,
          .fragmentShader = "aov.frag",
          .pushSize = pushSize,
          .colorFormats = {kAovFormat, kAovFormat},
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true};
}
}  // namespace

AovPass::AovPass(const gpu::Context& ctx, bool withPoolAndWater)
    : groundPipeline(gpu::createGraphicsPipeline(ctx, aovPipeline("ground.vert", sizeof(shader::GroundParams)))),
      spherePipeline(gpu::createGraphicsPipeline(ctx, aovPipeline("sphere.vert", sizeof(shader::SphereParams)))),
      boxPipeline(gpu::createGraphicsPipeline(ctx, aovPipeline("box.vert", sizeof(shader::BoxParams)))) {
  if (withPoolAndWater) {
    wallsPipeline = gpu::createGraphicsPipeline(ctx, aovPipeline("pool_walls.vert", 0));
    floorPipeline = gpu::createGraphicsPipeline(ctx, aovPipeline("pool_floor.vert", sizeof(glm::uvec4)));
    gpu::GraphicsPipelineDesc water = aovPipeline("water_surface.vert", sizeof(shader::WaterSurfaceParams));
    water.topology = vk::PrimitiveTopology::eTriangleStrip;  // the renderer's water indices (waterGridStrips)
    waterPipeline = gpu::createGraphicsPipeline(ctx, water);
  }
}

void AovPass::declare(FrameGraph& graph, ResourceRef normalRef, const gpu::Image& normal, ResourceRef positionRef,
                      const gpu::Image& position, ResourceRef depthRef, const gpu::Image& depth,
                      const gpu::Buffer& frameUniforms, const shader::GroundParams& ground, const PoolDraw* pool,
                      const WaterDraw* water, const std::vector<shader::SphereParams>* spheres,
                      const std::vector<shader::BoxParams>* boxes) const {
  std::vector<std::pair<ResourceRef, Use>> uses{
      {normalRef, Use::ColorWrite}, {positionRef, Use::ColorWrite}, {depthRef, Use::DepthWrite}};
  if (water) {
    for (ResourceRef r : water->stateRefs) uses.push_back({r, Use::VertexStorageRead});
  }
  std::optional<WaterDraw> waterDraw;
  if (water) waterDraw = *water;
  std::optional<PoolDraw> poolDraw;
  if (pool) poolDraw = *pool;
  graph.pass("aov", std::move(uses),
             [this, &normal, &position, &depth, &frameUniforms, ground, poolDraw, waterDraw, spheres, boxes](PassContext& pc) {
               const auto& cmd = pc.cmd;
               // Where nothing is hit: no normal, and a position and depth at infinity.
               const float inf = std::numeric_limits<float>::infinity();
               vk::RenderingAttachmentInfo targets[] = {
                   attachment(normal, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                              vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}}),
                   attachment(position, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                              vk::ClearValue{.color = {std::array<float, 4>{inf, inf, inf, inf}}}),
               };
               auto depthTarget = attachment(depth, vk::ImageLayout::eDepthAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                                             vk::ClearValue{.depthStencil = {1.0f, 0}});
               cmd.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, normal.extent},
                                                    .layerCount = 1,
                                                    .colorAttachmentCount = 2,
                                                    .pColorAttachments = targets,
                                                    .pDepthAttachment = &depthTarget});
               setViewport(cmd, normal.extent);
               gpu::bindPipeline(cmd, groundPipeline, ground);
               gpu::DescriptorWrites().uniformBuffer(0, frameUniforms).bind(cmd, groundPipeline, pc.descriptors);
               gpu::draw(cmd, kGroundVertices);
               if (poolDraw) drawPool(cmd, pc.descriptors, *wallsPipeline, *floorPipeline, frameUniforms, *poolDraw, nullptr);
               drawObjects(cmd, pc.descriptors, spherePipeline, boxPipeline, frameUniforms, nullptr, nullptr, *spheres, *boxes);
               if (waterDraw) {
                 gpu::bindPipeline(cmd, *waterPipeline, waterDraw->params);
                 gpu::DescriptorWrites()
                     .uniformBuffer(0, frameUniforms)
                     .storageBuffer(2, waterDraw->state())
                     .bind(cmd, *waterPipeline, pc.descriptors);
                 drawWater(cmd, *waterDraw);
               }
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

CameraMediumPass::CameraMediumPass(const gpu::Context& ctx)
    : pipeline(gpu::createComputePipeline(ctx, "camera_medium.comp", sizeof(shader::WaterSurfaceParams))) {}

void CameraMediumPass::declare(FrameGraph& graph, const WaterDraw& water, const gpu::Buffer& frameUniforms,
                               ResourceRef uniformsRef, const MediumDraw& medium, std::function<bool()> runIf) const {
  std::vector<std::pair<ResourceRef, Use>> uses{{medium.ref, Use::ComputeWrite}, {uniformsRef, Use::HostData}};
  for (ResourceRef r : water.stateRefs) uses.push_back({r, Use::ComputeRead});
  graph.pass("camera medium", std::move(uses), [this, water, &frameUniforms, medium](PassContext& pc) {
    gpu::bindPipeline(pc.cmd, pipeline, water.params);
    gpu::DescriptorWrites()
        .uniformBuffer(0, frameUniforms)
        .storageBuffer(1, *medium.buffer)
        .storageBuffer(2, water.state())
        .bind(pc.cmd, pipeline, pc.descriptors);
    gpu::dispatch(pc.cmd, 1);
  }, {.cached = true, .runIf = std::move(runIf)});
}

void declareImageCopy(FrameGraph& graph, const std::string& name, ResourceRef fromRef, const gpu::Image& from,
                      ResourceRef toRef, const gpu::Image& to) {
  graph.pass(name, {{fromRef, Use::TransferRead}, {toRef, Use::TransferWrite}}, [&from, &to](PassContext& pc) {
    pc.cmd.copyImage(from.handle(), vk::ImageLayout::eTransferSrcOptimal, to.handle(), vk::ImageLayout::eTransferDstOptimal,
                     vk::ImageCopy{.srcSubresource = {from.aspect, 0, 0, 1},
                                   .dstSubresource = {to.aspect, 0, 0, 1},
                                   .extent = {from.extent.width, from.extent.height, 1}});
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
