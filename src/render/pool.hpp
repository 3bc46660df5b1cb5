#pragma once
// The pool: its inner walls and terrain floor, and the caustics, the sun
// through the waves accumulated on the floor's mean plane
// (shaders_glsl/caustics.vert) by a cached pass, recorded again only when the
// water or the frame's uniforms (the sun) changed.
#include <optional>

#include "render/surfaces.hpp"
#include "render/water_draw.hpp"
#include "scene/scene.hpp"

namespace tp::render {

constexpr vk::Format kCausticsFormat = vk::Format::eR16G16B16A16Sfloat;  // the sky's format: blendable, sampled
constexpr uint32_t kWallVertices = 24;                                   // pool_walls.vert: four quads

// What other passes need of the pool: its uniforms, the spheres the water's
// rays can meet, the floor grid and its vertices, and the caustics (the caustics pass's
// target, or one texel of 1 when the scene has caustics off).
struct PoolDraw {
  const gpu::Buffer* uniforms = nullptr;
  const gpu::Buffer* objects = nullptr;
  const gpu::Buffer* floorIndices = nullptr;
  uint32_t floorIndexCount = 0;
  uint32_t floorGrid = 0;                      // vertices per side
  const gpu::Buffer* floorVertices = nullptr;  // the floor mesh's vertices (PoolModel::floorVertices)
  GraphImage caustics;
};

class Pool {
 public:
  Pool(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, bool gbuffer);
  const PoolDraw& draw() const { return draw_; }
  // The objects the water's rays meet, filled by the host before each frame.
  const gpu::Buffer& objectUniforms() const { return objectUniforms_; }
  // The caustics pass, when the scene has caustics.
  void declareCaustics(FrameGraph& graph, const WaterDraw& water, const FrameInputs& in) const;
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in) const;

 private:
  gpu::Buffer uniforms_, objectUniforms_, floorIndices_, floorVertices_;
  gpu::Image caustics_;
  PoolDraw draw_;
  gpu::Pipeline walls_, floor_;
  std::optional<gpu::Pipeline> causticsPipeline_;
};

// The walls, then the floor, with `set` holding what either reads.
void drawPool(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& walls,
              const gpu::Pipeline& floor, const Bindings& set, const PoolDraw& pool);

}  // namespace tp::render
