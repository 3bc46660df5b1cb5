#include "reference/reference_caustics.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "reference/reference_scene.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"
#include "shared/glass.h"
#include "shared/shading.h"

namespace tp::render {
namespace {

// How far above the water's rest level the photons start, in metres: above
// any wave the simulation's slope limits allow in a pool a few metres wide.
constexpr float kPhotonStartHeight = 4.0f;
// How far past the surface a refracted photon starts: far above float
// round-off at metres, far below any feature.
constexpr float kPastSurface = 1e-4f;

// The interpolated normal of the water's mesh at `hit`, facing up.
glm::vec3 waterNormalAt(const scene::Mesh& water, const std::vector<glm::vec3>& normals, const ReferenceHit& hit) {
  const uint32_t* corner = &water.indices[size_t(hit.triangle) * 3];
  const glm::vec2 b = hit.barycentric;
  const glm::vec3 n =
      glm::normalize((1.0f - b.x - b.y) * normals[corner[0]] + b.x * normals[corner[1]] + b.y * normals[corner[2]]);
  return n.y < 0.0f ? -n : n;
}

// Sends the sun's photons at the water: one per lattice point of the rest
// level (photonsPerTexelSide^2 a texel of `map`), each met by the water's
// mesh and handed to `follow(atLevel, onSurface, normal)`, which returns
// the texel it counts in (none: out of the map) and its weight. The map's
// ratio: the weights summed per texel over the photons a texel sends.
template <typename Follow>
void countPhotons(CausticsMap& map, const scene::Mesh& water, const std::vector<glm::vec3>& waterNormals,
                  glm::vec3 toSun, float level, uint32_t photonsPerTexelSide, Follow follow) {
  const ReferenceScene surface({water}, {});
  const float h = map.halfExtent;
  const uint32_t side = map.size * photonsPerTexelSide;
  const float spacing = 2.0f * h / float(side);
  std::vector<std::atomic<uint64_t>> counts(map.ratio.size());
  // Weights are counted in fixed point: atomic and the same sum in any order.
  constexpr double kUnit = 65536.0;
#pragma omp parallel for schedule(dynamic, 8)
  for (uint32_t j = 0; j < side; ++j) {
    for (uint32_t i = 0; i < side; ++i) {
      const glm::vec3 atLevel(-h + (float(i) + 0.5f) * spacing, level, -h + (float(j) + 0.5f) * spacing);
      const glm::vec3 start = atLevel + toSun * (kPhotonStartHeight / toSun.y);
      const ReferenceHit hit = surface.intersect(start, -toSun, 0.0f);
      if (!hit.hit()) continue;  // past the mesh's edge: no water there
      const std::optional<std::pair<size_t, float>> counted =
          follow(atLevel, start - hit.distance * toSun, waterNormalAt(water, waterNormals, hit));
      if (counted)
        counts[counted->first].fetch_add(uint64_t(std::lround(double(counted->second) * kUnit)),
                                         std::memory_order_relaxed);
    }
  }
  const double perPhoton = 1.0 / (kUnit * double(photonsPerTexelSide) * double(photonsPerTexelSide));
  for (size_t k = 0; k < counts.size(); ++k) map.ratio[k] = float(double(counts[k].load()) * perPhoton);
}

// The texel of `map` holding line xz, if any.
std::optional<size_t> texelOf(const CausticsMap& map, glm::vec2 xz) {
  const float texel = 2.0f * map.halfExtent / float(map.size);
  const float tx = std::floor((xz.x + map.halfExtent) / texel), tz = std::floor((xz.y + map.halfExtent) / texel);
  if (tx < 0.0f || tz < 0.0f || tx >= float(map.size) || tz >= float(map.size)) return std::nullopt;
  return size_t(tz) * map.size + size_t(tx);
}

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
  const ReferenceScene under(receivers.meshes, receivers.spheres);
  const shader::PoolParams pool = poolParams(scene);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  // Through flat water each photon would cross the level at its lattice
  // point: its light line, and the one it lands on.
  countPhotons(map, water, waterNormals, toSun, scene.water.level, photonsPerTexelSide,
               [&](glm::vec3, glm::vec3 onSurface, glm::vec3 n) -> std::optional<std::pair<size_t, float>> {
                 const glm::vec3 d = glm::normalize(glm::refract(-toSun, n, 1.0f / scene.water.ior));
                 if (d.y >= 0.0f) return std::nullopt;  // bent along or above the surface: it lights nothing under it
                 const glm::vec3 from = onSurface - kPastSurface * up;
                 const ReferenceHit landing = under.intersect(from, d, 0.0f);
                 if (!landing.hit()) return std::nullopt;
                 const std::optional<size_t> texel =
                     texelOf(map, shader::causticsLine(pool, toSun, from + landing.distance * d));
                 if (!texel) return std::nullopt;
                 return std::make_pair(*texel, 1.0f);
               });
  return map;
}

glm::vec2 mirrorPoint(glm::vec3 p, glm::vec3 toSun, float level) {
  const float t = (p.y - level) / toSun.y;
  return {p.x + t * toSun.x, p.z + t * toSun.z};
}

CausticsMap traceReflectedCaustics(const scene::Scene& scene, const scene::Mesh& water,
                                   const std::vector<glm::vec3>& waterNormals, const CausticReceivers& receivers,
                                   uint32_t size, uint32_t photonsPerTexelSide) {
  if (size < 2 || photonsPerTexelSide == 0) throw std::invalid_argument("traceReflectedCaustics: an empty grid");
  if (waterNormals.size() != water.positions.size())
    throw std::invalid_argument("traceReflectedCaustics: one normal per water vertex");
  const float half = 0.5f * scene.water.extent;
  CausticsMap map{size, half, half, std::vector<float>(size_t(size) * size, 0.0f)};
  const glm::vec3 toSun = sunDirection(scene.sky);
  if (toSun.y <= 0.0f) return map;
  const ReferenceScene above(receivers.meshes, receivers.spheres);
  const float level = scene.water.level, ior = scene.water.ior;
  const float flatReflectance = shader::fresnelDielectric(toSun.y, 1.0f, ior);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  // Each photon counts at the mirror point of where it lands, weighted by
  // its own reflectance over the flat water's: under flat water it lands
  // on the line up from its own lattice point, at weight 1.
  countPhotons(map, water, waterNormals, toSun, level, photonsPerTexelSide,
               [&](glm::vec3, glm::vec3 onSurface, glm::vec3 n) -> std::optional<std::pair<size_t, float>> {
                 const float cosIn = glm::dot(toSun, n);
                 if (cosIn <= 0.0f) return std::nullopt;  // met from behind its slope
                 const glm::vec3 d = glm::reflect(-toSun, n);
                 if (d.y <= 0.0f) return std::nullopt;  // reflected into the water again
                 const glm::vec3 from = onSurface + kPastSurface * up;
                 const ReferenceHit landing = above.intersect(from, d, 0.0f);
                 if (!landing.hit()) return std::nullopt;
                 const std::optional<size_t> texel =
                     texelOf(map, mirrorPoint(from + landing.distance * d, toSun, level));
                 if (!texel) return std::nullopt;
                 return std::make_pair(*texel, shader::fresnelDielectric(cosIn, 1.0f, ior) / flatReflectance);
               });
  return map;
}

}  // namespace tp::render
