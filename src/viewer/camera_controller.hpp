#pragma once
#include <glm/glm.hpp>

#include "scene/camera.hpp"

namespace tp::app {

// The viewer's camera controls, their constants in one place.
struct CameraControls {
  static constexpr double kOrbitRadiansPerPixel = 0.005;  // a mouse drag of 1 pixel turns the orbit by this
  static constexpr double kMaxElevationDegrees = 85.0;    // the orbit's pitch stays within +-this: short of the poles
  static constexpr double kZoomPerNotch = 0.9;            // one wheel notch forward multiplies the distance by this
  static constexpr double kMinDistance = 0.25;            // metres from the target, the zoom's range
  static constexpr double kMaxDistance = 100.0;
  static constexpr double kFlySpeed = 2.0;  // m/s with a key held
};

// Orbit, zoom and fly for a scene::Camera, on the CPU. The camera is kept as
// its target and, in double precision, its distance, azimuth (about +y) and
// elevation from there; the camera a move makes has up = +y and the home
// camera's field of view and planes. reset() returns the home camera itself.
class CameraController {
 public:
  explicit CameraController(const scene::Camera& home);

  const scene::Camera& camera() const { return camera_; }

  // Turns the position about the target: the azimuth by `yaw` radians about
  // +y, the elevation by `pitch` (clamped to +-kMaxElevationDegrees). The
  // target and the distance stay.
  void orbit(double yaw, double pitch);
  // Multiplies the distance to the target by kZoomPerNotch^notches (positive:
  // closer), clamped to [kMinDistance, kMaxDistance] (widened to take in the
  // home camera's distance).
  void zoom(double notches);
  // Moves position and target together by kFlySpeed * seconds along the
  // view's horizontal forward (times `forward`) and right (times `right`);
  // (forward, right) longer than 1 is shortened to 1.
  void fly(double forward, double right, double seconds);
  // Back to the home camera, bit for bit.
  void reset();
  // To this camera, bit for bit (the panel's edit); moves go on from it, and
  // reset() still returns home. Its distance widens the zoom's range if need be.
  void moveTo(const scene::Camera& camera);

 private:
  void place();  // camera_ from the orbit's state

  scene::Camera home_, camera_;
  glm::dvec3 target_{0.0};
  double distance_ = 1.0, azimuth_ = 0.0, elevation_ = 0.0;
  double minDistance_ = CameraControls::kMinDistance, maxDistance_ = CameraControls::kMaxDistance;
};

}  // namespace tp::app
