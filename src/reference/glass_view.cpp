#include "reference/glass_view.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shading/objects_model.hpp"

namespace tp::render {

scene::Scene glassSphereView() {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;
  s.ao.enabled = false;
  s.boxes.clear();
  s.spheres = {{.center = {0.0f, 0.9f, 0.0f}, .radius = 0.6f, .material = "glass", .ior = 1.5f}};
  s.camera.position = {0.4f, 1.3f, 2.6f};
  s.camera.target = {0.0f, 0.85f, 0.0f};
  return s;
}

scene::Scene glassBoxView() {
  scene::Scene s = glassSphereView();
  s.spheres.clear();
  s.boxes = {{.center = {0.0f, 0.8f, 0.0f},
              .size = {1.0f, 0.6f, 0.8f},
              .yawDegrees = 30.0f,
              .material = "glass",
              .ior = 1.5f}};
  return s;
}

std::vector<uint8_t> glassPixelMask(const RenderedFrame& aovs, const scene::Scene& placed) {
  std::vector<uint8_t> mask(size_t(aovs.width) * aovs.height, 0);
  if (aovs.position.size() != mask.size() * 4)
    throw std::invalid_argument("glassPixelMask: the frame has no position AOV");
  for (size_t k = 0; k < mask.size(); ++k) {
    const glm::vec3 p(aovs.position[k * 4], aovs.position[k * 4 + 1], aovs.position[k * 4 + 2]);
    for (const scene::Sphere& sphere : placed.spheres) {
      // On the surface to float round-off of a ray's hit at metres.
      if (scene::isGlass(sphere) && std::abs(glm::distance(p, sphere.center) - sphere.radius) < 1e-3f * sphere.radius) {
        mask[k] = 1;
      }
    }
    for (const scene::Box& box : placed.boxes) {
      if (!scene::isGlass(box)) continue;
      // On a face: in the box's frame, as far out as its half size along one axis.
      const shader::BoxParams b = boxParams(box);
      const glm::vec3 out = glm::abs(shader::toBoxFrame(p - glm::vec3(b.center), b.center.w)) / glm::vec3(b.halfSize);
      if (std::abs(std::max({out.x, out.y, out.z}) - 1.0f) < 1e-3f) mask[k] = 1;
    }
  }
  return mask;
}

}  // namespace tp::render
