#pragma once
// Arbitrary output variables for the EXR: world normal, world position and
// view depth of every surface, drawn into targets of their own by one pass,
// recorded only when a frame asks for them.
#include <optional>

#include "graph/readback.hpp"
#include "render/objects.hpp"
#include "render/pool.hpp"
#include "render/surfaces.hpp"
#include "render/water_draw.hpp"
#include "shared/ground.h"

namespace tp::render {

class Aovs {
 public:
  Aovs(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D frame, bool withPoolAndWater);
  // `pool` and `water`: null without water. `inView`: every object in view, glass too.
  void declare(FrameGraph& graph, const FrameInputs& in, const shader::GroundParams& ground, const PoolDraw* pool,
               const WaterDraw* water, const ObjectsInView& inView) const;
  // What a frame requests to read them back.
  std::vector<ResourceRef> readbackRefs() const { return {normalReadback_.ref.ref, positionReadback_.ref.ref}; }
  // xyz0 world normal and xyz world position with view depth in w, per pixel.
  std::vector<float> normals() const;
  std::vector<float> positions() const;

 private:
  vk::Extent2D frame_;
  gpu::Image normal_, position_, depth_;
  GraphImage normalRef_, positionRef_, depthRef_;
  Readback normalReadback_, positionReadback_;
  gpu::Pipeline ground_, spheres_, boxes_;
  std::optional<gpu::Pipeline> walls_, floor_, water_;
};

}  // namespace tp::render
