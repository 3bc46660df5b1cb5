#include "render/aovs.hpp"

#include <array>
#include <limits>

#include "gpu/commands.hpp"
#include "render/ground.hpp"
#include "render/pass_kinds.hpp"
#include "shared/objects.h"

namespace tp::render {
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

vk::DeviceSize bytes(vk::Extent2D e) { return vk::DeviceSize(e.width) * e.height * 16; }

}  // namespace

Aovs::Aovs(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D frame, bool withPoolAndWater)
    : frame_(frame),
      normalReadback_(ctx, graph, "normal readback", bytes(frame)),
      positionReadback_(ctx, graph, "position readback", bytes(frame)),
      ground_(gpu::createGraphicsPipeline(ctx, aovPipeline("ground.vert", sizeof(shader::GroundParams)))),
      spheres_(gpu::createGraphicsPipeline(ctx, aovPipeline("sphere.vert", sizeof(shader::SphereParams)))),
      boxes_(gpu::createGraphicsPipeline(ctx, aovPipeline("box.vert", sizeof(shader::BoxParams)))) {
  const auto usage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc;
  normal_ = gpu::createImage2D(ctx, frame, kAovFormat, usage, "normal AOV target");
  position_ = gpu::createImage2D(ctx, frame, kAovFormat, usage, "position AOV target");
  depth_ =
      gpu::createImage2D(ctx, frame, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment, "AOV depth target");
  normalRef_ = graph.image("normal", normal_);
  positionRef_ = graph.image("position", position_);
  depthRef_ = graph.image("aov depth", depth_);
  if (withPoolAndWater) {
    walls_ = gpu::createGraphicsPipeline(ctx, aovPipeline("pool_walls.vert", sizeof(shader::PoolWallsParams)));
    floor_ = gpu::createGraphicsPipeline(ctx, aovPipeline("pool_floor.vert", sizeof(glm::uvec4)));
    gpu::GraphicsPipelineDesc water = aovPipeline("water_surface.vert", sizeof(shader::WaterSurfaceParams));
    water.topology = vk::PrimitiveTopology::eTriangleStrip;  // the renderer's water indices (waterGridStrips)
    water_ = gpu::createGraphicsPipeline(ctx, water);
  }
}

void Aovs::declare(FrameGraph& graph, const FrameInputs& in, const shader::GroundParams& ground, const PoolDraw* pool,
                   const WaterDraw* water, const ObjectsInView& inView) const {
  std::optional<PoolDraw> poolDraw;
  if (pool) poolDraw = *pool;
  std::optional<WaterDraw> waterDraw;
  if (water) waterDraw = *water;
  graph.pass(passes::kAov, [this, in, ground, poolDraw, waterDraw, &inView](PassBuilder& pass) {
    const gpu::Image& normal = pass.attach(normalRef_, Use::ColorWrite);
    const gpu::Image& position = pass.attach(positionRef_, Use::ColorWrite);
    const gpu::Image& depth = pass.attach(depthRef_, Use::DepthWrite);
    // One set for every pipeline: each binds what its vertex shader reads.
    Bindings& set = pass.bindings().uniformBuffer(0, in.uniforms, Use::HostData);
    if (poolDraw) set.constantBuffer(1, *poolDraw->uniforms).constantStorageBuffer(5, *poolDraw->floorVertices);
    if (waterDraw) set.storageBuffer(2, waterDraw->state, Use::VertexStorageRead);
    return [this, &normal, &position, &depth, &set, ground, poolDraw, waterDraw, &inView](PassContext& pc) {
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
      renderTo(cmd, targets, &depthTarget, normal.extent, [&] {
        gpu::bindPipeline(cmd, ground_, ground);
        set.bind(cmd, ground_, pc.descriptors);
        gpu::draw(cmd, kGroundVertices);
        if (poolDraw) drawPool(cmd, pc.descriptors, *walls_, &*floor_, set, *poolDraw);
        drawObjects(cmd, pc.descriptors, spheres_, boxes_, set, inView);
        if (waterDraw) {
          gpu::bindPipeline(cmd, *water_, waterDraw->params);
          set.bind(cmd, *water_, pc.descriptors);
          drawWater(cmd, *waterDraw);
        }
      });
    };
  });
  declareReadback(graph, passes::kReadbackNormal, normalRef_, normalReadback_);
  declareReadback(graph, passes::kReadbackPosition, positionRef_, positionReadback_);
}

std::vector<float> Aovs::normals() const {
  return readFloats(normalReadback_.buffer, size_t(frame_.width) * frame_.height * 4);
}

std::vector<float> Aovs::positions() const {
  return readFloats(positionReadback_.buffer, size_t(frame_.width) * frame_.height * 4);
}

}  // namespace tp::render
