#pragma once
// Glass spheres, Wyman's two-interface refraction in image space (2005): a
// pass draws their back faces into a normal and view-depth target, then a
// pass draws their front faces over the frame, each pixel searching that
// target for where its refracted ray leaves (shaders_glsl/glass_back.frag,
// glass.frag). Declared only for a scene with glass; recorded only for a
// frame with glass spheres in view.
#include <vector>

#include "render/passes.hpp"
#include "shared/glass.h"

namespace tp::render {

constexpr vk::Format kGlassBackFormat = vk::Format::eR32G32B32A32Sfloat;  // outward normal, view depth

// The back faces' target and the depth buffer its draw tests against.
struct GlassTargets {
  Target backFaces, depth;
};

struct GlassPasses {
  explicit GlassPasses(const gpu::Context& ctx);
  // `spheres`: the glass spheres in view when the frame records. `sky` as the
  // background pass samples it; `nearest` fetches the back faces' texels.
  void declare(FrameGraph& graph, const GlassTargets& glass, const SurfaceTargets& frame, const MediumDraw& medium,
               ResourceRef skyRef, const gpu::Image& sky, vk::Sampler skySampler, vk::Sampler nearest,
               const gpu::Buffer& frameUniforms, const std::vector<shader::GlassSphereParams>* spheres) const;
  gpu::Pipeline back, front;
};

}  // namespace tp::render
