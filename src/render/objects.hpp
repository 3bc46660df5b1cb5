#pragma once
// The scene's spheres and boxes, one draw each, where the renderer says they
// are when the frame records (spheres may move from frame to frame); the
// pass is left out of a frame where none is in view.
#include <span>
#include <vector>

#include "render/glossy_probes.hpp"
#include "render/pool.hpp"
#include "render/surfaces.hpp"
#include "shared/objects.h"

namespace tp::render {

// The objects in view in the frame being recorded, filled by the renderer.
struct ObjectsInView {
  std::vector<shader::SphereParams> spheres;
  // Each sphere's glossy probe (render/glossy_probes), or kNoGlossyProbe:
  // it reads the sky's glossy map.
  std::vector<uint32_t> sphereProbes;
  std::vector<shader::BoxParams> boxes;
  bool empty() const { return spheres.empty() && boxes.empty(); }
};

class Objects {
 public:
  // `pool`: the pool, whose caustics light the objects' parts under the
  // water, or NoPool's stand-ins, which light nothing differently.
  Objects(const gpu::Context& ctx, FragmentNeeds needs, const PoolDraw& pool);
  // `probeMaps`: the glossy spheres' prefiltered probes, in probe order.
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in, const ObjectsInView& inView,
               std::vector<GraphImage> probeMaps) const;

 private:
  gpu::Pipeline spheres_, boxes_;
  const gpu::Buffer* poolUniforms_;
  const gpu::Buffer* floorVertices_;  // and the pool's baked light (shared/pool_light.h)
  GraphImage caustics_;
  SwappingBuffer waterCells_;
};

// Each sphere, then each box, with `set` holding what either pipeline reads,
// or for a sphere with a glossy probe, `probeSets`' set of its probe.
void drawObjects(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& spheres,
                 const gpu::Pipeline& boxes, const Bindings& set, const ObjectsInView& inView,
                 std::span<const Bindings* const> probeSets = {});

}  // namespace tp::render
