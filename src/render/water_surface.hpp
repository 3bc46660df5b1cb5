#pragma once
// The simulated water's surface, drawn straight from the simulation's state
// buffer over the frame: its front faces (seen from above) reflect the sky and
// refract the pool in the scene's refraction mode, its back faces (seen from
// below) reflect the pool and refract the sky. The apparent-depth mode reads
// the frame's image of the pool, copied before the water is drawn.
#include <optional>

#include "render/pool.hpp"
#include "render/surfaces.hpp"
#include "render/water_deferred.hpp"
#include "render/water_draw.hpp"
#include "scene/scene.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::render {

class WaterSurface {
 public:
  // `surfaces`: what the opaque surfaces need (surfaceNeeds); the water's
  // shaders need the same and may meet glass. `deferred`: the accurate
  // mode's surface seen from above shaded once per pixel (WaterDeferred),
  // rather than by its forward shader. `clearAmbient` (deferred only): the
  // water writes zero into the G-buffer's ambient image where it is seen,
  // for the resolve pass that takes AO after it (FragmentNeeds::clearAmbient).
  WaterSurface(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, FragmentNeeds surfaces,
               sim::GpuStepper& stepper, vk::Extent2D frame, bool deferred, bool clearAmbient);
  const WaterDraw& draw() const { return draw_; }
  // The step the grid is drawn at from the next frame on (shading/grid_detail.hpp);
  // returns whether it changed.
  bool setGridStep(uint32_t step) { return mesh_.setStep(step); }
  // The copy of the pool under the water, for the apparent-depth mode (else nothing).
  void declareUnderwater(FrameGraph& graph, const GraphImage& color) const;
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const PoolDraw& pool, const FrameInputs& in) const;
  // The side seen from above shaded deferred; none when it is drawn forward.
  const WaterDeferred* deferred() const { return deferred_ ? &*deferred_ : nullptr; }

 private:
  gpu::Pipeline below_;
  bool clearAmbient_;
  GridMesh mesh_;
  WaterDraw draw_;
  std::optional<gpu::Pipeline> above_;  // forward; none when the side from above is shaded deferred
  gpu::Image underwater_;
  std::optional<GraphImage> underwaterRef_;  // the apparent-depth mode's
  std::optional<WaterDeferred> deferred_;
};

}  // namespace tp::render
