#include "render/glossy_probes.hpp"

#include <cstring>
#include <limits>

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "render/sky_image.hpp"
#include "shading/pool_model.hpp"
#include "shared/glossy.h"

namespace tp::render {
namespace {

// The frame's uniforms as the probes read them: the light and the shadows'
// casters, the camera's parts fixed, so that a camera that moves (or a
// sample's jitter) leaves the probes as they are.
shader::FrameUniforms lightOnly(shader::FrameUniforms frame) {
  frame.view = frame.projection = frame.viewProjection = frame.inverseViewProjection = frame.inverseProjection =
      glm::mat4(1.0f);
  frame.cameraPosition = glm::vec4(0.0f);
  frame.viewport = glm::vec4(1.0f);
  frame.sampling = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
  return frame;
}

}  // namespace

GlossyProbes::Probe::Probe(const gpu::Context& ctx, FrameGraph& graph, size_t sphere)
    : sphere(sphere),
      image(gpu::createImage2D(ctx, {kGlossyProbeWidth, kGlossyProbeWidth / 2}, kSkyFormat,
                               vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled, "glossy probe")),
      imageRef(graph.image("glossy probe", image)),
      prefilter(ctx, kGlossyProbeWidth, kGlossyProbeWidth / 2, kGlossyProbeSampling),
      mapRef(graph.image("glossy probe map", prefilter.map())) {}

GlossyProbes::GlossyProbes(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene) {
  for (size_t k = 0; k < scene.spheres.size(); ++k) {
    if (scene.spheres[k].specular > 0.0f && !scene::isGlass(scene.spheres[k])) probes_.emplace_back(ctx, graph, k);
  }
  if (hasPool(scene) && scene.pool.wallSpecular > 0.0f) {
    probes_.emplace_back(ctx, graph, kPool);
    poolCentre_ = glm::vec4(shader::poolProbeCenter(scene.water.level, scene.ground.height), 0.0f);
  }
  if (probes_.empty()) return;
  pipeline_ = gpu::createComputePipeline(ctx, "glossy_probe.comp", sizeof(shader::GlossyProbeParams));
  light_ = gpu::createBuffer(ctx, sizeof(shader::FrameUniforms), vk::BufferUsageFlagBits::eUniformBuffer,
                             gpu::MemoryUse::Upload, "glossy probes' light");
  lightRef_ = graph.buffer("glossy probes' light", light_);
  flatCaustics_ = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(1.0f)}}, "flat water's caustics");
  flatCausticsRef_ = graph.image("flat water's caustics", flatCaustics_, vk::ImageLayout::eShaderReadOnlyOptimal);
  centres_.assign(probes_.size(), glm::vec4(0.0f));
}

uint32_t GlossyProbes::probeOf(size_t sphere) const {
  for (size_t p = 0; p < probes_.size(); ++p) {
    if (probes_[p].sphere == sphere) return uint32_t(p);
  }
  return kNoGlossyProbe;
}

std::vector<GraphImage> GlossyProbes::maps() const {
  std::vector<GraphImage> maps;
  for (const Probe& probe : probes_) {
    if (probe.sphere != kPool) maps.push_back(probe.mapRef);
  }
  return maps;
}

GraphImage GlossyProbes::poolMap() const {
  return !probes_.empty() && probes_.back().sphere == kPool ? probes_.back().mapRef : GraphImage{};
}

void GlossyProbes::declare(FrameGraph& graph, const FrameInputs& in, const PoolDraw& pool) {
  if (probes_.empty()) return;
  graph.pass(passes::kGlossyProbes,
             [this, in, pool](PassBuilder& pass) {
               std::vector<Bindings*> sets;
               for (const Probe& probe : probes_) {
                 sets.push_back(&pass.bindings()
                                     .uniformBuffer(0, lightRef_, Use::HostData)
                                     .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData)
                                     .sampledImage(1, in.sky, in.equirect, Use::ComputeSample)
                                     .storageImage(2, probe.imageRef, Use::ComputeWrite)
                                     .constantBuffer(3, *pool.uniforms)
                                     .constantBuffer(4, *pool.objects)
                                     .sampledImage(6, flatCausticsRef_, in.clamp, Use::ComputeSample)
                                     .sampledImage(7, in.glossy, in.equirect, Use::ComputeSample)
                                     .constantStorageBuffer(8, *pool.floorVertices));
               }
               return [this, sets](PassContext& pc) {
                 for (size_t p = 0; p < probes_.size(); ++p) {
                   gpu::bindPipeline(pc.cmd, pipeline_, shader::GlossyProbeParams{centres_[p]});
                   sets[p]->bind(pc.cmd, pipeline_, pc.descriptors);
                   gpu::dispatchCovering(pc.cmd, pipeline_, kGlossyProbeWidth, kGlossyProbeWidth / 2);
                 }
               };
             },
             {.cached = true, .runIf = {}});
  for (Probe& probe : probes_)
    probe.prefilter.declare(graph, probe.imageRef, in.equirect, probe.mapRef, passes::kGlossyProbePrefilter);
}

void GlossyProbes::update(FrameGraph& graph, const shader::FrameUniforms& frame, const scene::Scene& placed) {
  if (probes_.empty()) return;
  bool changed = false;
  const float waterY = hasPool(placed) ? placed.water.level : -std::numeric_limits<float>::infinity();
  for (size_t p = 0; p < probes_.size(); ++p) {
    const size_t sphere = probes_[p].sphere;
    const glm::vec4 centre = sphere == kPool
                                 ? poolCentre_
                                 : glm::vec4(shader::glossyProbeEye(placed.spheres.at(sphere).center,
                                                                    placed.spheres.at(sphere).radius, waterY),
                                             0.0f);
    changed |= centre != centres_[p];
    centres_[p] = centre;
  }
  const shader::FrameUniforms light = lightOnly(frame);
  if (std::memcmp(light_.mapped, &light, sizeof(light)) != 0) {
    std::memcpy(light_.mapped, &light, sizeof(light));
    changed = true;
  }
  if (changed) graph.touch(lightRef_.ref);
}

}  // namespace tp::render
