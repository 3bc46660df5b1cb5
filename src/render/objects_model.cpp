#include "render/objects_model.hpp"

#include <glm/gtc/constants.hpp>

namespace tp::render {

shader::SceneObjects sceneObjects(const scene::Scene& scene) {
  shader::SceneObjects objects{};
  objects.count = {uint32_t(scene.spheres.size()), 0u, 0u, 0u};
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    objects.spheres[i] = glm::vec4(scene.spheres[i].center, scene.spheres[i].radius);
    objects.sphereAlbedo[i] = glm::vec4(scene.spheres[i].albedo, 0.0f);
  }
  return objects;
}

shader::SphereParams sphereParams(const scene::Sphere& sphere) {
  return {glm::vec4(sphere.center, sphere.radius), glm::vec4(sphere.albedo, 0.0f),
          glm::uvec4(kSphereStacks, kSphereSlices, 0u, 0u)};
}

scene::Mesh sphereMesh(const scene::Sphere& sphere, const std::string& name) {
  scene::Mesh m{name, {}, {}};
  for (uint32_t j = 0; j <= kSphereStacks; ++j) {
    for (uint32_t i = 0; i <= kSphereSlices; ++i) {
      const float phi = glm::two_pi<float>() * float(i) / float(kSphereSlices);
      const float theta = glm::pi<float>() * float(j) / float(kSphereStacks);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      m.positions.push_back(sphere.center + sphere.radius * n);
    }
  }
  const uint32_t row = kSphereSlices + 1;
  for (uint32_t j = 0; j < kSphereStacks; ++j) {
    for (uint32_t i = 0; i < kSphereSlices; ++i) {
      const uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});  // outward: theta grows downwards, phi towards +z
    }
  }
  return m;
}

}  // namespace tp::render
