#include "viewer/camera_controller.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::app {
namespace {

constexpr double kMaxElevation = CameraControls::kMaxElevationDegrees * std::numbers::pi / 180.0;

}  // namespace

CameraController::CameraController(const scene::Camera& home) : home_(home) { reset(); }

void CameraController::reset() { moveTo(home_); }

void CameraController::moveTo(const scene::Camera& camera) {
  camera_ = camera;
  target_ = glm::dvec3(camera.target);
  const glm::dvec3 offset = glm::dvec3(camera.position) - target_;
  distance_ = glm::length(offset);
  minDistance_ = std::min(minDistance_, distance_);
  maxDistance_ = std::max(maxDistance_, distance_);
  // A camera straight above or below its target has no azimuth: 0 serves.
  azimuth_ = std::atan2(offset.x, offset.z);
  elevation_ = distance_ > 0.0 ? std::asin(std::clamp(offset.y / distance_, -1.0, 1.0)) : 0.0;
}

void CameraController::place() {
  const glm::dvec3 direction(std::cos(elevation_) * std::sin(azimuth_), std::sin(elevation_),
                             std::cos(elevation_) * std::cos(azimuth_));
  camera_.target = glm::vec3(target_);
  camera_.position = glm::vec3(target_ + distance_ * direction);
  camera_.up = glm::vec3(0.0f, 1.0f, 0.0f);
}

void CameraController::orbit(double yaw, double pitch) {
  azimuth_ = std::remainder(azimuth_ + yaw, 2.0 * std::numbers::pi);
  elevation_ = std::clamp(elevation_ + pitch, -kMaxElevation, kMaxElevation);
  place();
}

void CameraController::zoom(double notches) {
  distance_ = std::clamp(distance_ * std::pow(CameraControls::kZoomPerNotch, notches), minDistance_, maxDistance_);
  place();
}

void CameraController::fly(double forward, double right, double seconds) {
  glm::dvec2 amount(forward, right);
  if (glm::length(amount) > 1.0) amount = glm::normalize(amount);
  // The view looks from the position towards the target: against the offset.
  const glm::dvec3 ahead(-std::sin(azimuth_), 0.0, -std::cos(azimuth_));
  const glm::dvec3 side(std::cos(azimuth_), 0.0, -std::sin(azimuth_));  // ahead x +y
  target_ += CameraControls::kFlySpeed * seconds * (amount.x * ahead + amount.y * side);
  place();
}

}  // namespace tp::app
