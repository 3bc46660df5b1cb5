#include "render/pool.hpp"

#include <array>
#include <cstring>
#include <mutex>

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "render/pass_kinds.hpp"
#include "render/sky_image.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_light.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/water.h"

namespace tp::render {

namespace {

// The pool's baked light (shading/pool_light.hpp) for its model (whose
// parameters have no light around yet).
// The last bake is kept: a renderer made again for the same pool and sky
// (the viewer's at each resize, a sequence's) takes it instead of baking
// for a third of a second again.
PoolLight bakedLight(const scene::Scene& scene, const PoolModel& model, const Sky& sky) {
  struct Bake {
    shader::PoolParams pool;
    scene::Sky sky;
    std::vector<scene::Box> boxes;
    PoolLight light;
  };
  static std::mutex mutex;
  static std::optional<Bake> last;
  const std::lock_guard lock(mutex);
  if (!last || std::memcmp(&last->pool, &model.params, sizeof(model.params)) != 0 || !(last->sky == scene.sky) ||
      last->boxes != scene.boxes) {
    last = Bake{model.params, scene.sky, scene.boxes,
                bakePoolLight(
                    model.params, model.floorVertices, [&](glm::vec3 d) { return sky.radiance(d); },
                    PoolLightSun{sky.light().sunDirection, sky.light().sunIrradiance}, opaqueBoxes(scene))};
  }
  return last->light;
}

}  // namespace

Pool::Pool(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, const Sky& sky, FragmentNeeds needs,
           const gpu::Buffer& objects, const SwappingBuffer& waterCells)
    : floorMesh_(ctx, kPoolFloorGrid, false, "pool floor"),
      walls_(gpu::createGraphicsPipeline(
          ctx, opaquePipeline("pool_walls.vert", "pool_walls.frag", sizeof(shader::PoolWallsParams), needs))),
      floor_(gpu::createGraphicsPipeline(
          ctx, opaquePipeline("pool_floor.vert", "pool_floor.frag", sizeof(glm::uvec4), needs))),
      // No light, so no variants but with and without the G-buffer.
      floorDepth_(gpu::createGraphicsPipeline(ctx, opaquePipeline("pool_floor.vert", "pool_floor_depth.frag",
                                                                  sizeof(glm::uvec4), {.gbuffer = needs.gbuffer}))),
      cover_(gpu::createGraphicsPipeline(ctx, [&] {
        gpu::GraphicsPipelineDesc desc =
            opaquePipeline("pool_cover.vert", "pool_floor_depth.frag", sizeof(glm::vec4), {.gbuffer = needs.gbuffer});
        desc.colorWrites = false;
        return desc;
      }())) {
  if (needs.gbuffer) {
    wallsUnder_ = gpu::createGraphicsPipeline(ctx, opaquePipeline("pool_walls.vert", "pool_floor_depth.frag",
                                                                  sizeof(shader::PoolWallsParams), {.gbuffer = true}));
  }
  const PoolModel model = poolModel(scene);
  const PoolLight light = bakedLight(scene, model, sky);
  const shader::PoolParams pool = model.params;
  params_ = pool;
  floorTop_ = pool.terrain.w;
  uniforms_ = gpu::createFilledBuffer(ctx, &pool, sizeof(pool), vk::BufferUsageFlagBits::eUniformBuffer,
                                      gpu::MemoryUse::Upload, "pool uniforms");
  floorVertices_ = gpu::createFilledBuffer(ctx, light.floorAndLight, vk::BufferUsageFlagBits::eStorageBuffer,
                                           gpu::MemoryUse::Device, "pool floor vertices and light");
  draw_ = PoolDraw{&uniforms_, &objects, &floorMesh_, &floorVertices_, {}, waterCells};
  if (scene.render.caustics) {
    caustics_ =
        gpu::createImage2D(ctx, {kCausticsSize, kCausticsSize}, kCausticsFormat,
                           vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled, "caustics");
    draw_.caustics = graph.image("caustics", caustics_);
    causticsMesh_.emplace(ctx, scene.water.grid + 2, true, "caustics grid");
    causticsPipeline_ = gpu::createGraphicsPipeline(ctx, {.vertexShader = "caustics.vert",
                                                          .fragmentShader = "caustics.frag",
                                                          .pushSize = sizeof(shader::WaterSurfaceParams),
                                                          .colorFormats = {kCausticsFormat},
                                                          .topology = vk::PrimitiveTopology::eTriangleStrip,
                                                          .additive = true});
  } else {
    // The floor lit as through flat water: one texel of 1, uploaded once.
    caustics_ = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(1.0f)}}, "no caustics");
    draw_.caustics = graph.image("caustics", caustics_, vk::ImageLayout::eShaderReadOnlyOptimal);
  }
}

void Pool::declareCaustics(FrameGraph& graph, const WaterDraw& water, const FrameInputs& in) const {
  if (!causticsPipeline_) return;
  graph.pass(passes::kCaustics,
             [this, water, in](PassBuilder& pass) {
               const gpu::Image& target = pass.attach(draw_.caustics, Use::ColorWrite);
               Bindings& set = pass.bindings()
                                   .uniformBuffer(0, in.uniforms, Use::HostData)
                                   .storageBuffer(2, water.state, Use::VertexStorageRead)
                                   .constantBuffer(3, uniforms_);
               return [this, water, &target, &set](PassContext& pc) {
                 auto colorTarget =
                     attachment(target, vk::ImageLayout::eColorAttachmentOptimal, vk::AttachmentLoadOp::eClear,
                                vk::ClearValue{.color = {std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f}}});
                 renderTo(pc.cmd, std::span(&colorTarget, 1), nullptr, target.extent, [&] {
                   gpu::bindPipeline(pc.cmd, *causticsPipeline_, water.params);
                   set.bind(pc.cmd, *causticsPipeline_, pc.descriptors);
                   causticsMesh_->draw(pc.cmd);
                 });
               };
             },
             {.cached = true, .runIf = {}});
}

void Pool::declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
                   std::function<Drawn()> drawn, GraphImage wallProbe) const {
  graph.pass(passes::kPool, [this, targets, in, drawn, wallProbe](PassBuilder& pass) {
    attachSurfaces(pass, targets, false);
    Bindings& set = pass.bindings()
                        .uniformBuffer(0, in.uniforms, Use::HostData)
                        .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData)
                        .constantBuffer(1, uniforms_)
                        .sampledImage(2, draw_.caustics, in.clamp, Use::FragmentSample)
                        .uniformBuffer(3, in.medium, Use::FragmentUniformRead)
                        .sampledImage(4, in.glossy, in.equirect, Use::FragmentSample)
                        .sampledImage(7, wallProbe ? wallProbe : in.glossy, in.equirect, Use::FragmentSample)
                        .constantStorageBuffer(5, floorVertices_)
                        .storageBuffer(6, draw_.waterCells, Use::FragmentStorageRead);
    return [this, targets, &set, drawn](PassContext& pc) {
      const Drawn how = drawn();
      const gpu::Pipeline* floorPipeline = how.floor == Floor::Lit              ? &floor_
                                           : how.floor == Floor::DepthAndNormal ? &floorDepth_
                                                                                : nullptr;
      drawSurfaces(pc.cmd, targets, false, [&] {
        if (how.coverAt) {
          gpu::bindPipeline(pc.cmd, cover_, glm::vec4(*how.coverAt, 0.0f, 0.0f, 0.0f));
          set.bind(pc.cmd, cover_, pc.descriptors);
          gpu::draw(pc.cmd, kCoverVertices);
        }
        // The bands wholly under the cut give their depth and normal alone.
        uint32_t lit = TP_POOL_WALL_BANDS;
        if (how.wallsCut && wallsUnder_) {
          for (lit = 0; lit < TP_POOL_WALL_BANDS; ++lit)
            if (shader::poolWallBandTop(params_, lit) <= *how.wallsCut) break;
        }
        drawPoolWalls(pc.cmd, pc.descriptors, walls_, set, 0, lit);
        if (lit < TP_POOL_WALL_BANDS)
          drawPoolWalls(pc.cmd, pc.descriptors, *wallsUnder_, set, lit, TP_POOL_WALL_BANDS - lit);
        if (floorPipeline) drawPoolFloor(pc.cmd, pc.descriptors, *floorPipeline, set, draw_);
      });
    };
  });
}

NoPool::NoPool(const gpu::Context& ctx, FrameGraph& graph, const gpu::Buffer& objects,
               const shader::GroundParams& ground) {
  shader::PoolParams none{};
  none.ground = ground;
  uniforms_ = gpu::createFilledBuffer(ctx, &none, sizeof(none), vk::BufferUsageFlagBits::eUniformBuffer,
                                      gpu::MemoryUse::Upload, "no pool uniforms");
  const std::vector<glm::vec4> vertex(1, glm::vec4(0.0f));
  floorVertices_ = gpu::createFilledBuffer(ctx, vertex, vk::BufferUsageFlagBits::eStorageBuffer, gpu::MemoryUse::Device,
                                           "no pool floor vertices");
  caustics_ = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(1.0f)}}, "no caustics");
  const std::vector<shader::WaterCell> cell(1, shader::WaterCell{});
  waterCell_ = gpu::createFilledBuffer(ctx, cell, vk::BufferUsageFlagBits::eStorageBuffer, gpu::MemoryUse::Device,
                                       "no water cells");
  draw_ = PoolDraw{
      &uniforms_,
      &objects,
      nullptr,
      &floorVertices_,
      graph.image("caustics", caustics_, vk::ImageLayout::eShaderReadOnlyOptimal),
      {{graph.buffer("no water cells", waterCell_).ref}, [this]() -> const gpu::Buffer& { return waterCell_; }}};
}

void drawPoolWalls(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& walls,
                   const Bindings& set, uint32_t first, uint32_t count) {
  if (count == 0) return;
  gpu::bindPipeline(cmd, walls, shader::PoolWallsParams{glm::uvec4(first, count, 0u, 0u)});
  set.bind(cmd, walls, arena);
  gpu::draw(cmd, 24 * count);  // pool_walls.vert: four quads a band
}

void drawPoolFloor(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& floor,
                   const Bindings& set, const PoolDraw& pool) {
  gpu::bindPipeline(cmd, floor, glm::uvec4(pool.floor->vertices(), 0u, 0u, 0u));
  set.bind(cmd, floor, arena);
  pool.floor->draw(cmd);
}

void drawPool(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& walls,
              const gpu::Pipeline* floor, const Bindings& set, const PoolDraw& pool) {
  drawPoolWalls(cmd, arena, walls, set, 0, TP_POOL_WALL_BANDS);
  if (floor) drawPoolFloor(cmd, arena, *floor, set, pool);
}

}  // namespace tp::render
