#include "shading/objects_model.hpp"

#include <algorithm>
#include <glm/gtc/constants.hpp>

namespace tp::render {

shader::SceneObjects sceneObjects(const scene::Scene& scene, float waterTop) {
  shader::SceneObjects objects{};
  std::vector<scene::Sphere> spheres = scene.spheres;
  std::vector<scene::Box> boxes = scene.boxes;
  // Boxes turn about the vertical only: their lowest point is half their height down.
  const auto sphereBelow = std::stable_partition(
      spheres.begin(), spheres.end(), [&](const scene::Sphere& s) { return s.center.y - s.radius < waterTop; });
  const auto boxBelow = std::stable_partition(
      boxes.begin(), boxes.end(), [&](const scene::Box& b) { return b.center.y - 0.5f * b.size.y < waterTop; });
  objects.count = {uint32_t(spheres.size()), uint32_t(boxes.size()), uint32_t(sphereBelow - spheres.begin()),
                   uint32_t(boxBelow - boxes.begin())};
  for (size_t i = 0; i < spheres.size(); ++i) {
    objects.spheres[i] = glm::vec4(spheres[i].center, spheres[i].radius);
    objects.sphereAlbedo[i] = glm::vec4(spheres[i].albedo, 0.0f);
    objects.sphereMaterial[i] =
        glm::vec4(spheres[i].specular, spheres[i].roughness, scene::isGlass(spheres[i]) ? spheres[i].ior : 0.0f, 0.0f);
  }
  for (size_t i = 0; i < boxes.size(); ++i) {
    const shader::BoxParams box = boxParams(boxes[i]);
    objects.boxCenter[i] = box.center;
    objects.boxHalfSize[i] = glm::vec4(glm::vec3(box.halfSize), scene::isGlass(boxes[i]) ? boxes[i].ior : 0.0f);
    objects.boxAlbedo[i] = box.albedo;
  }
  return objects;
}

shader::BoxParams boxParams(const scene::Box& box) {
  return {glm::vec4(box.center, glm::radians(box.yawDegrees)), glm::vec4(0.5f * box.size, 0.0f),
          glm::vec4(box.albedo, 0.0f)};
}

std::vector<shader::BoxParams> opaqueBoxes(const scene::Scene& scene) {
  std::vector<shader::BoxParams> boxes;
  for (const scene::Box& b : scene.boxes)
    if (!scene::isGlass(b)) boxes.push_back(boxParams(b));
  return boxes;
}

scene::Mesh boxMesh(const scene::Box& box, const std::string& name) {
  const shader::BoxParams p = boxParams(box);
  const glm::vec3 ax = shader::boxAxisX(p.center.w), ay(0.0f, 1.0f, 0.0f), az = shader::boxAxisZ(p.center.w);
  scene::Mesh m{name, {}, {}};
  for (int k = 0; k < 8; ++k) {  // corner k: bit 0 +x, bit 1 +y, bit 2 +z
    const glm::vec3 s((k & 1) ? 1.0f : -1.0f, (k & 2) ? 1.0f : -1.0f, (k & 4) ? 1.0f : -1.0f);
    const glm::vec3 local = s * glm::vec3(p.halfSize);
    m.positions.push_back(glm::vec3(p.center) + local.x * ax + local.y * ay + local.z * az);
  }
  // Counter-clockwise seen from outside.
  m.indices = {1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2, 2, 6, 7, 2, 7, 3,
               0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1};
  return m;
}

shader::SphereParams sphereParams(const scene::Sphere& sphere) {
  return {glm::vec4(sphere.center, sphere.radius), glm::vec4(sphere.albedo, 0.0f),
          glm::uvec4(kSphereStacks, kSphereSlices, 0u, 0u), glm::vec4(sphere.specular, sphere.roughness, 0.0f, 0.0f)};
}

uint32_t sphereSlot(const shader::SceneObjects& objects, const scene::Sphere& sphere) {
  for (uint32_t i = 0; i < objects.count.x; ++i) {
    if (objects.spheres[i] == glm::vec4(sphere.center, sphere.radius)) return i;
  }
  return shader::kSkipNoSphere;
}

shader::GlassSphereParams glassSphereParams(const scene::Sphere& sphere, unsigned searchSteps, uint32_t slot) {
  const shader::SphereParams shape = sphereParams(sphere);
  return {shape.sphere, shape.albedo, shape.tessellation, glm::vec4(sphere.ior, 0.0f, 0.0f, 0.0f),
          glm::uvec4(searchSteps, slot, 0u, 0u)};
}

shader::GlassBoxParams glassBoxParams(const scene::Box& box) {
  const shader::BoxParams shape = boxParams(box);
  return {shape.center, shape.halfSize, shape.albedo, glm::vec4(box.ior, 0.0f, 0.0f, 0.0f)};
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
