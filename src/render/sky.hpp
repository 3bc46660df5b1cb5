#pragma once
// The sky: the procedural one, filled by a compute pass on the first frame
// (cached: its parameters are fixed), or an image, uploaded once (then no
// pass at all), each with its mip chain (SkyMips); and the background that
// shows it behind everything, drawn in the ground's pass.
#include <functional>
#include <optional>

#include "render/sky_image.hpp"
#include "render/sky_mips.hpp"
#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shading/sky_model.hpp"
#include "shared/sky.h"

namespace tp::render {

class Sky {
 public:
  // `gbuffer`: the surfaces' targets have the G-buffer.
  Sky(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene, bool gbuffer);
  GraphImage image() const { return ref_; }
  // What lights the scene: the sun, and the sky's irradiance with the
  // ground's light below the horizon (sceneLight).
  const SkyLight& light() const { return light_; }
  // Its radiance along unit d without the sun's disc, on the CPU, as the
  // texture holds it (what bakes the pool's light: shading/pool_light.hpp).
  glm::vec3 radiance(glm::vec3 d) const;
  // The procedural sky's pass; nothing for a sky image.
  void declareSky(FrameGraph& graph) const;
  // The sky behind everything, seen through each pixel's view ray: declares
  // what it reads in `pass`, and returns what draws it in that pass's
  // rendering, after the surfaces drawn there, where their depth left the
  // far plane (the depth test before the shader leaves out the pixels they
  // cover). Its colour and the G-buffer's clear (lib/gbuffer.glsl's
  // writeNoSurface); no depth.
  std::function<void(PassContext&)> background(PassBuilder& pass, const FrameInputs& in) const;

 private:
  // A sky image's levels past the first, once, as it is loaded.
  void fillMips(const gpu::Context& ctx);

  SkyMips mips_;
  gpu::Image image_;
  GraphImage ref_;
  SkyLight light_;
  std::optional<SkyImage> cpuImage_;  // a sky image's texels, for radiance()
  shader::SkyParams params_{};
  std::optional<gpu::Pipeline> skyPipeline_;  // the procedural sky's
  gpu::Pipeline background_;
};

}  // namespace tp::render
