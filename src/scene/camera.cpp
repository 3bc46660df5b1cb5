#include "scene/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

#include "base/number_text.hpp"

namespace tp::scene {

glm::mat4 Camera::view() const { return glm::lookAtRH(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
  p[1][1] = -p[1][1];  // Vulkan's clip y points down
  return p;
}

namespace {

// A key's position, target and fov as one point to interpolate.
struct Pose {
  glm::vec3 position, target;
  float fov;
};

Pose poseOf(const CameraKeyframe& k) { return {k.position, k.target, k.fovYDegrees}; }

Pose mix(const Pose& a, const Pose& b, float f) {
  return {glm::mix(a.position, b.position, f), glm::mix(a.target, b.target, f), a.fov + (b.fov - a.fov) * f};
}

// Catmull-Rom between p1 and p2 at s in [0, 1], p0 and p3 their neighbours.
template <typename T>
T catmullRom(const T& p0, const T& p1, const T& p2, const T& p3, float s) {
  const float s2 = s * s, s3 = s2 * s;
  return 0.5f * (2.0f * p1 + (p2 - p0) * s + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * s2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * s3);
}

Pose pathPose(const Camera& c, float t) {
  const auto& path = c.path;
  if (t <= path.front().time) return poseOf(path.front());
  if (t >= path.back().time) return poseOf(path.back());
  const size_t i = size_t(std::upper_bound(path.begin(), path.end(), t,
                                           [](float time, const CameraKeyframe& k) { return time < k.time; }) -
                          path.begin()) -
                   1;
  const float s = (t - path[i].time) / (path[i + 1].time - path[i].time);
  if (c.interpolation == "linear") return mix(poseOf(path[i]), poseOf(path[i + 1]), s);
  const Pose p0 = poseOf(path[i > 0 ? i - 1 : i]), p1 = poseOf(path[i]), p2 = poseOf(path[i + 1]),
             p3 = poseOf(path[std::min(i + 2, path.size() - 1)]);
  return {catmullRom(p0.position, p1.position, p2.position, p3.position, s),
          catmullRom(p0.target, p1.target, p2.target, p3.target, s), catmullRom(p0.fov, p1.fov, p2.fov, p3.fov, s)};
}

void requireCameraFinite(const glm::vec3& v, const char* field) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
    throw std::runtime_error(std::string(field) + " must be finite");
  }
}

}  // namespace

Camera cameraAt(const Camera& camera, float t) {
  Camera at = camera;
  if (!camera.path.empty()) {
    const Pose pose = pathPose(camera, t);
    at.position = pose.position;
    at.target = pose.target;
    at.fovYDegrees = pose.fov;
  } else if (camera.turntableSeconds > 0.0f) {
    const float angle = glm::two_pi<float>() * std::fmod(t / camera.turntableSeconds, 1.0f);
    const glm::vec3 arm = camera.position - camera.target;
    const float c = std::cos(angle), s = std::sin(angle);
    at.position = camera.target + glm::vec3(c * arm.x - s * arm.z, arm.y, s * arm.x + c * arm.z);
  }
  return at;
}

void validateCamera(const Camera& c) {
  if (!(c.fovYDegrees > 0.0f && c.fovYDegrees < 180.0f)) {
    throw std::runtime_error("camera fov " + base::numberText(c.fovYDegrees) + " degrees is outside (0, 180)");
  }
  if (!(c.nearPlane > 0.0f && c.farPlane > c.nearPlane && std::isfinite(c.farPlane))) {
    throw std::runtime_error("camera near/far planes must satisfy 0 < near < far < infinity");
  }
  glm::vec3 forward = c.target - c.position;
  if (!(glm::length(forward) > 0.0f)) throw std::runtime_error("camera target equals its position");
  if (!(glm::length(glm::cross(forward, c.up)) > 1e-6f * glm::length(forward) * glm::length(c.up))) {
    throw std::runtime_error("camera up vector is parallel to its viewing direction");
  }
  if (std::find(kCameraInterpolation.begin(), kCameraInterpolation.end(), c.interpolation) ==
      kCameraInterpolation.end()) {
    throw std::runtime_error("camera.interpolation must be linear or catmull_rom, got '" + c.interpolation + "'");
  }
  if (!(c.turntableSeconds >= 0.0f && std::isfinite(c.turntableSeconds))) {
    throw std::runtime_error("camera.turntable must be 0 (off) or a positive number of seconds per turn");
  }
  if (c.turntableSeconds > 0.0f && !c.path.empty()) {
    throw std::runtime_error("camera.turntable and camera.path each move the camera: give one");
  }
  for (size_t k = 0; k < c.path.size(); ++k) {
    const CameraKeyframe& key = c.path[k];
    requireCameraFinite(key.position, "camera.path[].position");
    requireCameraFinite(key.target, "camera.path[].target");
    if (!(key.time >= 0.0f && key.time <= 1e6f)) throw std::runtime_error("camera.path[].time must be 0 to 1e6");
    if (k > 0 && !(key.time > c.path[k - 1].time)) {
      throw std::runtime_error("camera.path[].time must increase from key to key");
    }
    Camera still = c;
    still.path.clear();
    still.position = key.position;
    still.target = key.target;
    still.fovYDegrees = key.fovYDegrees;
    validateCamera(still);  // each key a camera that can form a view
  }
}

}  // namespace tp::scene
