#pragma once
// The pool: its inner walls and terrain floor, and the caustics, the sun
// through the waves accumulated on the floor's mean plane
// (shaders_glsl/caustics.vert) by a cached pass, recorded again only when the
// water or the frame's uniforms (the sun) changed.
#include <functional>
#include <optional>

#include "render/sky.hpp"
#include "render/surfaces.hpp"
#include "render/water_draw.hpp"
#include "scene/scene.hpp"
#include "shared/ground.h"
#include "shared/pool.h"

namespace tp::render {

// The caustics hold two values a texel, the ratio and the layers that reach
// it (caustics.frag): a format every device must blend and sample linearly.
constexpr vk::Format kCausticsFormat = vk::Format::eR16G16Sfloat;
constexpr uint32_t kCoverVertices = 6;  // pool_cover.vert: one quad

// What other passes need of the pool: its uniforms, the objects the rays
// cast in shaders meet (the renderer's, filled before each frame), the floor
// grid and its vertices, the caustics (the caustics pass's target, or one
// texel of 1 when the scene has caustics off), and the water's cells, which
// say what lies under its surface (lib/sun_through_waves.glsl).
struct PoolDraw {
  const gpu::Buffer* uniforms = nullptr;
  const gpu::Buffer* objects = nullptr;
  const GridMesh* floor = nullptr;  // the floor grid at the frame's step
  // The floor mesh's vertices (PoolModel::floorVertices), then the pool's
  // baked light (shared/pool_light.h).
  const gpu::Buffer* floorVertices = nullptr;
  GraphImage caustics;
  SwappingBuffer waterCells;
};

class Pool {
 public:
  // `objects`: the objects the rays cast in shaders meet (shader::SceneObjects).
  // `waterCells`: the simulation's state (WaterDraw::state). `sky`: what
  // lights the pool's baked light.
  Pool(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, const Sky& sky, FragmentNeeds needs,
       const gpu::Buffer& objects, const SwappingBuffer& waterCells);
  const PoolDraw& draw() const { return draw_; }
  // The caustics pass, when the scene has caustics.
  void declareCaustics(FrameGraph& graph, const WaterDraw& water, const FrameInputs& in) const;
  // How the floor is drawn in a frame.
  enum class Floor {
    Lit,             // seen: its light (pool_floor.frag)
    DepthAndNormal,  // seen only through the water, whose shader shows it, and read by
                     // the SSAO: its depth and normal alone (pool_floor_depth.frag)
    None,            // seen only through the water, and read by nothing
  };
  // How the pool is drawn in a frame: its floor, and where the camera sees
  // everything in the pool through the water below a height, and nothing
  // reads the depth there but the water, a level square at that height,
  // drawn first into the depth alone (pool_cover.vert), so that the depth
  // test leaves out the walls and objects under it. Where the SSAO reads
  // that depth, the walls are lit above the height alone and give their
  // depth and normal below it (shared/pool.h's PoolWallsParams).
  struct Drawn {
    Floor floor;
    std::optional<float> coverAt;
    std::optional<float> wallsCut;
  };
  // `drawn` is asked as each frame records.
  // `wallProbe`: what the glossy walls above the water reflect, the pool's
  // probe (render/glossy_probes), or none: the sky's glossy map.
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in, std::function<Drawn()> drawn,
               GraphImage wallProbe = {}) const;
  // The floor's highest point, in metres.
  float floorTop() const { return floorTop_; }
  // The step the floor grid is drawn at from the next frame on
  // (shading/grid_detail.hpp); returns whether it changed.
  bool setFloorStep(uint32_t step) { return floorMesh_.setStep(step); }
  uint32_t floorStep() const { return floorMesh_.step(); }
  // The step the caustics draw the water's grid at, the surface's; returns
  // whether it changed.
  bool setCausticsStep(uint32_t step) { return causticsMesh_ && causticsMesh_->setStep(step); }

 private:
  gpu::Buffer uniforms_, floorVertices_;
  GridMesh floorMesh_;
  std::optional<GridMesh> causticsMesh_;  // the water's grid reaching the walls
  gpu::Image caustics_;
  PoolDraw draw_;
  gpu::Pipeline walls_, floor_, floorDepth_, cover_;
  std::optional<gpu::Pipeline> wallsUnder_;  // with the G-buffer: the walls' bands under the cut
  shader::PoolParams params_;
  float floorTop_ = 0.0f;
  std::optional<gpu::Pipeline> causticsPipeline_;
};

// What stands for the pool in a scene without one, for the passes that read
// it whatever the scene (the objects, the glass): uniforms of zero but for
// the ground (no hole, no water: no caustics reach anything), one floor
// vertex, one caustics texel of 1, one water cell.
class NoPool {
 public:
  NoPool(const gpu::Context& ctx, FrameGraph& graph, const gpu::Buffer& objects, const shader::GroundParams& ground);
  const PoolDraw& draw() const { return draw_; }

 private:
  gpu::Buffer uniforms_, floorVertices_, waterCell_;
  gpu::Image caustics_;
  PoolDraw draw_;
};

// `count` of the walls' bands from `first` (shared/pool.h), with `set`
// holding what the pipeline reads.
void drawPoolWalls(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& walls,
                   const Bindings& set, uint32_t first, uint32_t count);
// The floor.
void drawPoolFloor(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& floor,
                   const Bindings& set, const PoolDraw& pool);
// The walls, all their bands, then the floor (none: no floor).
void drawPool(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& walls,
              const gpu::Pipeline* floor, const Bindings& set, const PoolDraw& pool);

}  // namespace tp::render
