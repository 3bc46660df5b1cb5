#pragma once
// The scene's spheres and boxes, one draw each, where the renderer says they
// are when the frame records (spheres may move from frame to frame); the
// pass is left out of a frame where none is in view.
#include <vector>

#include "render/pool.hpp"
#include "render/surfaces.hpp"
#include "shared/objects.h"

namespace tp::render {

// The objects in view in the frame being recorded, filled by the renderer.
struct ObjectsInView {
  std::vector<shader::SphereParams> spheres;
  std::vector<shader::BoxParams> boxes;
  bool empty() const { return spheres.empty() && boxes.empty(); }
};

class Objects {
 public:
  // `pool`: the pool, whose caustics light the objects' parts under the
  // water, or NoPool's stand-ins, which light nothing differently.
  Objects(const gpu::Context& ctx, FragmentNeeds needs, const PoolDraw& pool);
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
               const ObjectsInView& inView) const;

 private:
  gpu::Pipeline spheres_, boxes_;
  const gpu::Buffer* poolUniforms_;
  const gpu::Buffer* floorVertices_;  // and the pool's baked light (shared/pool_light.h)
  GraphImage caustics_;
  SwappingBuffer waterCells_;
};

// Each sphere, then each box, with `set` holding what either pipeline reads.
void drawObjects(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& spheres,
                 const gpu::Pipeline& boxes, const Bindings& set, const ObjectsInView& inView);

}  // namespace tp::render
