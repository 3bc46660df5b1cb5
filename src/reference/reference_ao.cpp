#include "reference/reference_ao.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/pixel_rotation.hpp"
#include "reference/reference_scene.hpp"
#include "reference/row_progress.hpp"
#include "shading/hammersley.hpp"
#include "shading/water_model.hpp"

namespace tp::render {
namespace {

// The occluders of a frame: its triangles less the water and the glass
// (transparent, and drawn after the SSAO, which does not see them) and the
// spheres' tessellations (cast exactly).
ReferenceScene occluders(const scene::Scene& scene, const sim::WaterState* water, float time, bool exactSpheres) {
  scene::Scene solid = scene;
  std::erase_if(solid.spheres, [](const scene::Sphere& s) { return scene::isGlass(s); });
  std::erase_if(solid.boxes, [](const scene::Box& b) { return scene::isGlass(b); });
  std::vector<scene::Mesh> opaque;
  for (auto& mesh : sceneMeshes(solid, water, time)) {
    if (mesh.name == "water" || (exactSpheres && mesh.name.rfind("sphere", 0) == 0)) continue;
    opaque.push_back(std::move(mesh));
  }
  return ReferenceScene(opaque, exactSpheres ? scene::sceneAt(solid, time).spheres : std::vector<scene::Sphere>{});
}

// A right-handed orthonormal basis (t, b, n) about the unit normal n, valid for
// every direction: its one division is by sign(n.z) + n.z, never less than 1
// in magnitude (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
struct Basis {
  glm::vec3 t, b, n;
};
Basis basisAbout(glm::vec3 n) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z), c = n.x * n.y * a;
  return {{1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x}, {c, sign + n.y * n.y * a, -n.y}, n};
}

void validate(std::span<const float> position, std::span<const float> normal, uint32_t width, uint32_t height,
              const ReferenceAoOptions& options) {
  const size_t expected = size_t(width) * height * 4;
  if (position.size() != expected || normal.size() != expected)
    throw std::invalid_argument("reference AO: position and normal must be RGBA images of " + std::to_string(width) +
                                " x " + std::to_string(height) + " (" + std::to_string(expected) + " floats), got " +
                                std::to_string(position.size()) + " and " + std::to_string(normal.size()));
  if (!(std::isfinite(options.radius) && options.radius > 0.0f))
    throw std::invalid_argument("reference AO: radius must be positive and finite, got " +
                                std::to_string(options.radius));
  if (options.rays == 0) throw std::invalid_argument("reference AO: rays must be at least 1");
  if (!options.originOffset.empty() && options.originOffset.size() != size_t(width) * height)
    throw std::invalid_argument("reference AO: originOffset must have one value per pixel");
}

}  // namespace

std::vector<float> referenceAmbientOcclusion(const scene::Scene& scene, const sim::WaterState* water, float time,
                                             std::span<const float> position, std::span<const float> normal,
                                             uint32_t width, uint32_t height, const ReferenceAoOptions& options) {
  validate(position, normal, width, height, options);
  const ReferenceScene bvh = occluders(scene, water, time, options.exactSpheres);
  std::vector<float> ao(size_t(width) * height, 1.0f);
  RowProgress progress(height, options.progress);
#pragma omp parallel for schedule(dynamic, 1)
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t k = size_t(y) * width + x;
      const glm::vec3 p(position[k * 4], position[k * 4 + 1], position[k * 4 + 2]);
      const glm::vec3 m(normal[k * 4], normal[k * 4 + 1], normal[k * 4 + 2]);
      const float length = glm::length(m);
      // No surface (the sky), or no normal to integrate about: nothing occludes.
      if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) || !(length > 0.0f) ||
          !std::isfinite(length))
        continue;
      const Basis basis = basisAbout(m / length);
      const float lift =
          options.originOffset.empty() ? kSurfaceOffset : std::max(kSurfaceOffset, options.originOffset[k]);
      const glm::vec3 origin = p + lift * basis.n;
      const glm::vec2 offset = pixelRotation(k);
      uint32_t hits = 0;
      for (uint32_t i = 0; i < options.rays; ++i) {
        const glm::vec2 u = hammersley(i, options.rays);
        const glm::vec3 local = cosineHemisphere({wrapUnit(u.x + offset.x), wrapUnit(u.y + offset.y)});
        const glm::vec3 dir = glm::normalize(local.x * basis.t + local.y * basis.b + local.z * basis.n);
        const ReferenceHit hit = bvh.intersect(origin, dir, 0.0f);
        if (hit.hit() && hit.distance < options.radius) ++hits;
      }
      ao[k] = 1.0f - float(hits) / float(options.rays);
    }
    progress.rowDone();
  }
  return ao;
}

}  // namespace tp::render
