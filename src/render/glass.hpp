#pragma once
// Glass spheres, Wyman's two-interface refraction in image space (2005): a
// pass draws their back faces into a normal and view-depth target, then a
// pass draws their front faces over the frame, each pixel searching that
// target for where its refracted ray leaves (shaders_glsl/glass_back.frag,
// glass.frag); glass boxes, drawn in the second pass, follow the exact path.
// The rays that leave look up the scene by the analytic casts the water's
// rays use. Declared only for a scene with glass; recorded only for a frame
// with glass in view.
#include <optional>
#include <vector>

#include "render/pool.hpp"
#include "render/surfaces.hpp"
#include "shared/glass.h"

namespace tp::render {

constexpr vk::Format kGlassBackFormat = vk::Format::eR32G32B32A32Sfloat;  // outward normal, view depth

class Glass {
 public:
  // Makes the back faces' target and the depth buffer its draw tests against.
  // `needs`: the shadows and the water's scattering (no G-buffer: glass is
  // drawn after AO). `pool`: the pool, or NoPool's stand-ins (their
  // uniforms hold the ground the rays leaving the glass meet).
  // `scene`: whether it has glass spheres, boxes or both.
  Glass(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D frame, FragmentNeeds needs, const PoolDraw& pool,
        const scene::Scene& scene);
  // `spheres`, `boxes`: the glass in view when the frame records.
  void declare(FrameGraph& graph, const SurfaceTargets& frame, const FrameInputs& in,
               const std::vector<shader::GlassSphereParams>& spheres,
               const std::vector<shader::GlassBoxParams>& boxes) const;

 private:
  gpu::Image backFaces_, depth_;
  PoolDraw pool_;
  GraphImage backFacesRef_, depthRef_;
  std::optional<gpu::Pipeline> back_, front_;  // for a scene with glass spheres
  std::optional<gpu::Pipeline> boxFront_;      // for a scene with glass boxes
};

}  // namespace tp::render
