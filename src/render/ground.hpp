#pragma once
// The checkered ground plane around the pool's hole, depth tested; the first
// surface. It is drawn into images of its own, cleared, with the sky behind
// it, in a cached pass: the two read nothing but the frame's uniforms (the
// camera, the sun and sky, the shadows' casters) and the sky's texture, so a
// frame where these did not change keeps them. Each frame then begins with
// their copy into the frame's targets, which the other surfaces draw over:
// the sky drawn where they will be is drawn over, and where they leave the
// far plane it is what the frame shows, as if drawn after them.
#include <functional>
#include <optional>

#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shading/screen_rect.hpp"
#include "shared/ground.h"

namespace tp::render {

constexpr uint32_t kGroundVertices = 24;  // ground.vert: four quads around the pool's hole

class Ground {
 public:
  // `frame`: the frame's size; `gbuffer`: whether the frame's targets have a G-buffer.
  Ground(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, FragmentNeeds needs, vk::Extent2D frame,
         bool gbuffer);
  const shader::GroundParams& params() const { return params_; }
  // The images the ground is drawn into, which each frame copies.
  const SurfaceTargets& drawn() const { return own_; }
  // The ground's pass, with `sky` (Sky::background) drawn after the ground
  // in it, and its copy into `targets`. `outOfObjectShadows`, asked as each
  // frame records: no sphere's or box's shadow can fall on the ground
  // (groundOutOfObjectShadows), so it draws without their code.
  // `copyOnly`, when given, is asked as each frame's copy records, unless
  // the ground was drawn since the last copy: the pixels to copy, those the
  // last frame drew over the ground (the rest hold the last copy's), or
  // none for all.
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
               std::function<bool()> outOfObjectShadows,
               const std::function<std::function<void(PassContext&)>(PassBuilder&)>& sky,
               std::function<std::optional<PixelRect>()> copyOnly) const;

 private:
  shader::GroundParams params_;
  gpu::Image color_, depth_, normal_, ambient_;
  SurfaceTargets own_;  // the ground as drawn, the frame's targets' formats
  gpu::Pipeline pipeline_;
  // Without the spheres' and boxes' shadows; none when the scene's ground has none to leave out.
  std::optional<gpu::Pipeline> unshadowed_;
  mutable bool drawnSinceCopy_ = true;  // the ground's images differ from what the frame's targets hold
};

}  // namespace tp::render
