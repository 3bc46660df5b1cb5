#pragma once
#include <glm/glm.hpp>

namespace tp::scene {

struct Camera {
  glm::vec3 position{3.2f, 2.4f, 4.6f};
  glm::vec3 target{0.0f, 0.3f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDegrees = 50.0f;
  float nearPlane = 0.05f;
  float farPlane = 500.0f;
  bool operator==(const Camera&) const = default;

  // World to camera; the camera looks down -z with +y up (OpenGL and EXR convention).
  glm::mat4 view() const;
  // Camera to Vulkan clip space: y points down the image, depth runs 0..1.
  glm::mat4 projection(float aspect) const;
};

// Throws with the field and the bound when the camera cannot form a view.
void validateCamera(const Camera& camera);

}  // namespace tp::scene
