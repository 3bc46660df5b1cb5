#include "reference/reference_caustics.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "reference/reference_scene.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"
#include "shared/shading.h"

namespace tp::render {
namespace {

// How far above the water's rest level the photons start, in metres: above
// any wave the simulation's slope limits allow in a pool a few metres wide.
constexpr float kPhotonStartHeight = 4.0f;
// How far past the surface a refracted photon starts: far above float
// round-off at metres, far below any feature.
constexpr float kPastSurface = 1e-4f;

}  // namespace

float CausticsMap::at(glm::vec2 xz) const {
  const float texel = 2.0f * halfExtent / float(size);
  const glm::vec2 line = glm::clamp(xz, glm::vec2(-reach), glm::vec2(reach));
  const glm::vec2 g = glm::clamp((line + halfExtent) / texel - 0.5f, glm::vec2(0.0f), glm::vec2(float(size - 1)));
  const glm::uvec2 i = glm::min(glm::uvec2(g), glm::uvec2(size - 2));
  const glm::vec2 f = g - glm::vec2(i);
  auto r = [&](uint32_t x, uint32_t z) { return ratio[size_t(z) * size + x]; };
  return glm::mix(glm::mix(r(i.x, i.y), r(i.x + 1, i.y), f.x), glm::mix(r(i.x, i.y + 1), r(i.x + 1, i.y + 1), f.x),
                  f.y);
}

CausticsMap traceCaustics(const scene::Scene& scene, const scene::Mesh& water,
                          const std::vector<glm::vec3>& waterNormals, const CausticReceivers& receivers, uint32_t size,
                          uint32_t photonsPerTexelSide) {
  if (size < 2 || photonsPerTexelSide == 0) throw std::invalid_argument("traceCaustics: an empty grid");
  if (waterNormals.size() != water.positions.size())
    throw std::invalid_argument("traceCaustics: one normal per water vertex");
  CausticsMap map{size, 0.5f * scene.water.extent, causticsReach(scene, size),
                  std::vector<float>(size_t(size) * size, 0.0f)};
  const glm::vec3 toSun = sunDirection(scene.sky);
  if (toSun.y <= 0.0f) return map;
  const ReferenceScene surface({water}, {}), under(receivers.meshes, receivers.spheres);
  const shader::PoolParams pool = poolParams(scene);
  const float h = map.halfExtent, level = scene.water.level;
  const uint32_t side = size * photonsPerTexelSide;
  const float spacing = 2.0f * h / float(side), texel = 2.0f * h / float(size);
  std::vector<std::atomic<uint32_t>> counts(map.ratio.size());
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
#pragma omp parallel for schedule(dynamic, 8)
  for (uint32_t j = 0; j < side; ++j) {
    for (uint32_t i = 0; i < side; ++i) {
      // Through flat water the photon would cross the level at this lattice point: its light line.
      const glm::vec3 atLevel(-h + (float(i) + 0.5f) * spacing, level, -h + (float(j) + 0.5f) * spacing);
      const glm::vec3 start = atLevel + toSun * (kPhotonStartHeight / toSun.y);
      const ReferenceHit hit = surface.intersect(start, -toSun, 0.0f);
      if (!hit.hit()) continue;  // past the mesh's edge: no water there
      const uint32_t* corner = &water.indices[size_t(hit.triangle) * 3];
      const glm::vec2 b = hit.barycentric;
      glm::vec3 n = glm::normalize((1.0f - b.x - b.y) * waterNormals[corner[0]] + b.x * waterNormals[corner[1]] +
                                   b.y * waterNormals[corner[2]]);
      if (n.y < 0.0f) n = -n;
      const glm::vec3 d = glm::normalize(glm::refract(-toSun, n, 1.0f / scene.water.ior));
      if (d.y >= 0.0f) continue;  // bent along or above the surface: it lights nothing under it
      const glm::vec3 from = start - hit.distance * toSun - kPastSurface * up;
      const ReferenceHit landing = under.intersect(from, d, 0.0f);
      if (!landing.hit()) continue;
      const glm::vec2 line = shader::causticsLine(pool, toSun, from + landing.distance * d);
      const float tx = std::floor((line.x + h) / texel), tz = std::floor((line.y + h) / texel);
      if (tx < 0.0f || tz < 0.0f || tx >= float(size) || tz >= float(size)) continue;  // no texel holds it
      counts[size_t(tz) * size + size_t(tx)].fetch_add(1, std::memory_order_relaxed);
    }
  }
  // Each photon carries spacing^2 of the beam's light lines; flat water
  // leaves each on its own.
  const float perPhoton = 1.0f / float(photonsPerTexelSide * photonsPerTexelSide);
  for (size_t k = 0; k < counts.size(); ++k) map.ratio[k] = float(counts[k].load()) * perPhoton;
  return map;
}

}  // namespace tp::render
