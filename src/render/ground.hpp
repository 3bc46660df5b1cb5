#pragma once
// The checkered ground plane around the pool's hole, depth tested; the first
// surface. It is drawn into images of its own, cleared, in a cached pass: it
// reads nothing but the frame's uniforms (the camera, the sun and sky, the
// shadows' casters), so a frame whose uniforms did not change keeps it. Each
// frame then begins with their copy into the frame's targets, which the other
// surfaces draw over.
#include <functional>
#include <optional>

#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shared/ground.h"

namespace tp::render {

constexpr uint32_t kGroundVertices = 24;  // ground.vert: four quads around the pool's hole

class Ground {
 public:
  // `frame`: the frame's size; `gbuffer`: whether the frame's targets have a G-buffer.
  Ground(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, FragmentNeeds needs, vk::Extent2D frame,
         bool gbuffer);
  const shader::GroundParams& params() const { return params_; }
  // The ground's pass and its copy into `targets`. `outOfObjectShadows`,
  // asked as each frame records: no sphere's or box's shadow can fall on the
  // ground (groundOutOfObjectShadows), so it draws without their code.
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
               std::function<bool()> outOfObjectShadows) const;

 private:
  shader::GroundParams params_;
  gpu::Image color_, depth_, normal_, ambient_;
  SurfaceTargets own_;  // the ground as drawn, the frame's targets' formats
  gpu::Pipeline pipeline_;
  // Without the spheres' and boxes' shadows; none when the scene's ground has none to leave out.
  std::optional<gpu::Pipeline> unshadowed_;
};

}  // namespace tp::render
