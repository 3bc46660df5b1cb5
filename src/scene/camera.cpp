#include "scene/camera.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

namespace tp::scene {

glm::mat4 Camera::view() const { return glm::lookAtRH(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
  p[1][1] = -p[1][1];  // Vulkan's clip y points down
  return p;
}

void validateCamera(const Camera& c) {
  if (!(c.fovYDegrees > 0.0f && c.fovYDegrees < 180.0f)) {
    throw std::runtime_error("camera fov " + std::to_string(c.fovYDegrees) + " degrees is outside (0, 180)");
  }
  if (!(c.nearPlane > 0.0f && c.farPlane > c.nearPlane && std::isfinite(c.farPlane))) {
    throw std::runtime_error("camera near/far planes must satisfy 0 < near < far < infinity");
  }
  glm::vec3 forward = c.target - c.position;
  if (!(glm::length(forward) > 0.0f)) throw std::runtime_error("camera target equals its position");
  if (!(glm::length(glm::cross(forward, c.up)) > 1e-6f * glm::length(forward) * glm::length(c.up))) {
    throw std::runtime_error("camera up vector is parallel to its viewing direction");
  }
}

}  // namespace tp::scene
