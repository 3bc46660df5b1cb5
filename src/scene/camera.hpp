#pragma once
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tp::scene {

// The default scene's view: a camera's, and a path key's where it leaves one out.
inline constexpr glm::vec3 kDefaultCameraPosition{3.4f, 1.45f, 4.3f};
inline constexpr glm::vec3 kDefaultCameraTarget{0.0f, -0.25f, 0.0f};
inline constexpr float kDefaultFovYDegrees = 55.0f;

// Where the camera stands, what it looks at and how wide it sees at a time
// (seconds from the scene's start).
struct CameraKeyframe {
  float time = 0.0f;
  glm::vec3 position = kDefaultCameraPosition;
  glm::vec3 target = kDefaultCameraTarget;
  float fovYDegrees = kDefaultFovYDegrees;
  bool operator==(const CameraKeyframe&) const = default;
};

// The ways between two keyframes: straight, or a Catmull-Rom spline through
// them (uniform in the keys, its ends' tangents from the end keys repeated).
inline const std::vector<std::string> kCameraInterpolation{"linear", "catmull_rom"};

struct Camera {
  glm::vec3 position = kDefaultCameraPosition;
  glm::vec3 target = kDefaultCameraTarget;
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDegrees = kDefaultFovYDegrees;
  float nearPlane = 0.05f;
  float farPlane = 500.0f;
  // The camera moves along `path` (held before its first key and after its
  // last), or turns about the target's vertical from where it stands, once
  // every `turntableSeconds` (from +x towards +z), or stands still.
  std::vector<CameraKeyframe> path = {};
  std::string interpolation = "linear";  // linear | catmull_rom
  float turntableSeconds = 0.0f;         // 0: no turntable
  bool operator==(const Camera&) const = default;

  // World to camera; the camera looks down -z with +y up (OpenGL and EXR convention).
  glm::mat4 view() const;
  // Camera to Vulkan clip space: y points down the image, depth runs 0..1.
  glm::mat4 projection(float aspect) const;
};

// Throws with the field and the bound when the camera cannot form a view,
// or its path or turntable cannot move it.
void validateCamera(const Camera& camera);

// Whether the camera moves with time (a path or a turntable).
inline bool isAnimated(const Camera& camera) { return !camera.path.empty() || camera.turntableSeconds > 0.0f; }

// The camera as it stands at time t: its path's or turntable's position,
// target and field of view, the rest as it is; still, it is the camera.
Camera cameraAt(const Camera& camera, float t);

}  // namespace tp::scene
