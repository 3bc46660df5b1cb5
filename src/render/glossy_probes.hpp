#pragma once
// What a glossy sphere reflects: the scene around it, its objects left out,
// seen from its centre (or just over the water, shared/glossy.h's
// glossyProbeEye) into an equirectangular probe (glossy_probe.comp) and
// prefiltered as the sky is (GlossyPrefilter). The raster's spheres look it
// up in the direction from that eye to where their mirror ray meets the
// ground or the water (glossyProbeDirection). The probes
// are cached passes: they run again only when a glossy sphere moves or the
// light changes (their own copy of the frame's uniforms, the camera left
// out, is touched only then). Glossy walls have one more, the pool's, seen
// from the pool's centre among the walls above the water, which those
// walls look up at what their mirror ray meets across the pool
// (poolProbeDirection). A scene without glossy spheres or walls has none.
#include <cstdint>
#include <deque>
#include <vector>

#include "render/glossy_prefilter.hpp"
#include "render/pool.hpp"
#include "render/surfaces.hpp"
#include "scene/scene.hpp"
#include "shared/frame.h"

namespace tp::render {

// A probe's width (its height is half): its finest level holds the lobe of
// an exponent of 415 (shared/glossy.h), roughness 0.26.
constexpr uint32_t kGlossyProbeWidth = 256;
// The prefilter's samples per texel: half the sky's, as a dragged sphere
// prefilters its probe every frame.
constexpr GlossySampling kGlossyProbeSampling{.environment = 32, .lobe = 32};
// No probe: the sphere reads the sky's glossy map.
constexpr uint32_t kNoGlossyProbe = UINT32_MAX;

class GlossyProbes {
 public:
  GlossyProbes(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene);
  bool empty() const { return probes_.empty(); }
  // The probe of the scene's sphere `sphere`, or kNoGlossyProbe.
  uint32_t probeOf(size_t sphere) const;
  // Each sphere's probe's prefiltered map, in probe order.
  std::vector<GraphImage> maps() const;
  // The pool's probe's, or none.
  GraphImage poolMap() const;

  // The pass that fills the probes and one prefilter pass each, cached.
  void declare(FrameGraph& graph, const FrameInputs& in, const PoolDraw& pool);
  // Before each frame: the frame's light and the spheres where they stand
  // (`placed`); touches the probes' inputs where either changed.
  void update(FrameGraph& graph, const shader::FrameUniforms& frame, const scene::Scene& placed);

 private:
  struct Probe {
    Probe(const gpu::Context& ctx, FrameGraph& graph, size_t sphere);
    size_t sphere;  // its index among the scene's spheres, or kPool
    gpu::Image image;
    GraphImage imageRef;
    GlossyPrefilter prefilter;
    GraphImage mapRef;
  };
  static constexpr size_t kPool = SIZE_MAX;
  std::deque<Probe> probes_;  // the spheres', then the pool's
  glm::vec4 poolCentre_{0.0f};
  gpu::Pipeline pipeline_;
  gpu::Buffer light_;  // shader::FrameUniforms of the frame, the camera left out
  GraphBuffer lightRef_;
  std::vector<glm::vec4> centres_;  // each probe's eye, pushed as it records
  gpu::Image flatCaustics_;         // the sun through flat water: the probes do not follow the waves
  GraphImage flatCausticsRef_;
};

}  // namespace tp::render
