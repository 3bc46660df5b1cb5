#pragma once
// The checkered ground plane around the pool's hole, depth tested; the first
// surface, so it clears depth and the G-buffer.
#include <functional>
#include <optional>

#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shared/ground.h"

namespace tp::render {

constexpr uint32_t kGroundVertices = 24;  // ground.vert: four quads around the pool's hole

class Ground {
 public:
  Ground(const gpu::Context& ctx, const scene::Scene& scene, FragmentNeeds needs);
  const shader::GroundParams& params() const { return params_; }
  // `outOfObjectShadows`, asked as each frame records: no sphere's or box's
  // shadow can fall on the ground (groundOutOfObjectShadows), so it draws
  // without their code.
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
               std::function<bool()> outOfObjectShadows) const;

 private:
  shader::GroundParams params_;
  gpu::Pipeline pipeline_;
  // Without the spheres' and boxes' shadows; none when the scene's ground has none to leave out.
  std::optional<gpu::Pipeline> unshadowed_;
};

}  // namespace tp::render
