// The viewer's camera controller (app/camera_controller) against exact
// answers: orbit keeps the target and distance and turns back to its start,
// the pitch stays inside its clamp, zoom scales the distance by the notch
// factor, flying moves position and target by one vector, reset restores the
// scene's camera to the bit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

#include "scene/scene.hpp"
#include "viewer/camera_controller.hpp"

namespace tp::test {
namespace {

using app::CameraController;
using app::CameraControls;
constexpr double kPi = std::numbers::pi;

double distance(const scene::Camera& c) { return glm::length(glm::dvec3(c.position) - glm::dvec3(c.target)); }
double elevationDegrees(const scene::Camera& c) {
  const glm::dvec3 offset = glm::dvec3(c.position) - glm::dvec3(c.target);
  return std::asin(offset.y / glm::length(offset)) * 180.0 / kPi;
}
// The pose bit for bit (memcmp: -0 is not 0), the animation by value.
bool sameBits(const scene::Camera& a, const scene::Camera& b) {
  const auto pose = [](const scene::Camera& c) {
    return std::array<float, 12>{c.position.x, c.position.y, c.position.z, c.target.x,    c.target.y,  c.target.z,
                                 c.up.x,       c.up.y,       c.up.z,       c.fovYDegrees, c.nearPlane, c.farPlane};
  };
  const auto pa = pose(a), pb = pose(b);
  return std::memcmp(pa.data(), pb.data(), sizeof pa) == 0 && a.path == b.path && a.interpolation == b.interpolation &&
         a.turntableSeconds == b.turntableSeconds;
}

// Float positions a few metres from the origin: a few float ulps of 4 m.
constexpr double kPositionTolerance = 2e-6;

}  // namespace

TEST(CameraController, StartsAtTheSceneCamera) {
  const scene::Camera home = scene::defaultScene().camera;
  EXPECT_TRUE(sameBits(CameraController(home).camera(), home));
}

TEST(CameraController, OrbitKeepsTheTargetAndTheDistance) {
  const scene::Camera home = scene::defaultScene().camera;
  CameraController controller(home);
  for (const auto& [yaw, pitch] : {std::pair{0.7, 0.2}, {-2.5, -0.4}, {3.0, 0.05}, {0.001, 0.0}}) {
    controller.orbit(yaw, pitch);
    const scene::Camera& c = controller.camera();
    EXPECT_TRUE(c.target == home.target);  // bitwise: the target never moves
    EXPECT_NEAR(distance(c), distance(home), kPositionTolerance);
    EXPECT_EQ(c.up, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_NO_THROW(scene::validateCamera(c));
  }
}

TEST(CameraController, AFullTurnOfYawReturnsToTheStart) {
  const scene::Camera home = scene::defaultScene().camera;
  CameraController once(home), steps(home);
  once.orbit(2.0 * kPi, 0.0);
  for (int k = 0; k < 360; ++k) steps.orbit(2.0 * kPi / 360.0, 0.0);
  for (const CameraController* c : {&once, &steps}) {
    EXPECT_NEAR(c->camera().position.x, home.position.x, kPositionTolerance);
    EXPECT_NEAR(c->camera().position.y, home.position.y, kPositionTolerance);
    EXPECT_NEAR(c->camera().position.z, home.position.z, kPositionTolerance);
  }
  // A quarter turn: the horizontal offset (x, z) turns to (z, -x) (yaw about +y).
  CameraController quarter(home);
  quarter.orbit(0.5 * kPi, 0.0);
  const glm::dvec3 before = glm::dvec3(home.position) - glm::dvec3(home.target);
  const glm::dvec3 after = glm::dvec3(quarter.camera().position) - glm::dvec3(home.target);
  EXPECT_NEAR(after.x, before.z, kPositionTolerance);
  EXPECT_NEAR(after.z, -before.x, kPositionTolerance);
  EXPECT_NEAR(after.y, before.y, kPositionTolerance);
}

TEST(CameraController, PitchStaysWithinItsClamp) {
  const scene::Camera home = scene::defaultScene().camera;
  CameraController controller(home);
  const double start = elevationDegrees(home);
  controller.orbit(0.0, 0.1);
  EXPECT_NEAR(elevationDegrees(controller.camera()), start + 0.1 * 180.0 / kPi, 1e-4);
  controller.orbit(0.0, 10.0);  // far past the pole
  EXPECT_NEAR(elevationDegrees(controller.camera()), CameraControls::kMaxElevationDegrees, 1e-4);
  EXPECT_NO_THROW(scene::validateCamera(controller.camera()));
  controller.orbit(1.0, -20.0);
  EXPECT_NEAR(elevationDegrees(controller.camera()), -CameraControls::kMaxElevationDegrees, 1e-4);
  EXPECT_NO_THROW(scene::validateCamera(controller.camera()));
  EXPECT_NEAR(distance(controller.camera()), distance(home), kPositionTolerance);
}

TEST(CameraController, ZoomScalesTheDistanceByTheNotchFactor) {
  const scene::Camera home = scene::defaultScene().camera;
  const double d0 = distance(home);
  for (double notches : {1.0, 3.0, -2.0, 0.5}) {
    CameraController controller(home);
    controller.zoom(notches);
    EXPECT_NEAR(distance(controller.camera()), d0 * std::pow(CameraControls::kZoomPerNotch, notches),
                kPositionTolerance)
        << notches;
    EXPECT_TRUE(controller.camera().target == home.target);
    // Along the same line: the direction to the camera does not change.
    const glm::dvec3 before = glm::normalize(glm::dvec3(home.position) - glm::dvec3(home.target));
    const glm::dvec3 after = glm::normalize(glm::dvec3(controller.camera().position) - glm::dvec3(home.target));
    EXPECT_NEAR(glm::length(after - before), 0.0, 1e-6);
  }
  CameraController in(home), out(home);
  in.zoom(1000.0);
  out.zoom(-1000.0);
  EXPECT_NEAR(distance(in.camera()), CameraControls::kMinDistance, 1e-6);
  EXPECT_NEAR(distance(out.camera()), CameraControls::kMaxDistance, 1e-4);
}

TEST(CameraController, FlyMovesPositionAndTargetByTheSameHorizontalVector) {
  const scene::Camera home = scene::defaultScene().camera;
  const glm::dvec3 view = glm::dvec3(home.target) - glm::dvec3(home.position);
  const glm::dvec3 ahead = glm::normalize(glm::dvec3(view.x, 0.0, view.z));
  const glm::dvec3 right = glm::cross(ahead, glm::dvec3(0.0, 1.0, 0.0));
  const double metres = CameraControls::kFlySpeed * 0.5;
  const std::pair<glm::dvec2, glm::dvec3> cases[] = {
      {{1.0, 0.0}, metres * ahead},                          // W
      {{-1.0, 0.0}, -metres * ahead},                        // S
      {{0.0, 1.0}, metres * right},                          // D
      {{0.0, -1.0}, -metres * right},                        // A
      {{1.0, 1.0}, metres * glm::normalize(ahead + right)},  // W and D: no faster
  };
  for (const auto& [keys, expected] : cases) {
    CameraController controller(home);
    controller.fly(keys.x, keys.y, 0.5);
    const scene::Camera& c = controller.camera();
    const glm::dvec3 targetMoved = glm::dvec3(c.target) - glm::dvec3(home.target);
    const glm::dvec3 positionMoved = glm::dvec3(c.position) - glm::dvec3(home.position);
    EXPECT_NEAR(glm::length(targetMoved - expected), 0.0, kPositionTolerance) << keys.x << "," << keys.y;
    EXPECT_NEAR(glm::length(positionMoved - targetMoved), 0.0, kPositionTolerance) << keys.x << "," << keys.y;
    EXPECT_EQ(targetMoved.y, 0.0);
  }
}

TEST(CameraController, ResetRestoresTheSceneCameraToTheBit) {
  scene::Camera home = scene::defaultScene().camera;
  home.fovYDegrees = 37.0f;
  home.position = {-1.3f, 0.7f, 2.9f};
  CameraController controller(home);
  controller.orbit(1.1, -0.3);
  controller.zoom(4.0);
  controller.fly(1.0, -1.0, 0.8);
  EXPECT_FALSE(sameBits(controller.camera(), home));
  EXPECT_EQ(controller.camera().fovYDegrees, home.fovYDegrees);
  controller.reset();
  EXPECT_TRUE(sameBits(controller.camera(), home));
  // And it moves from there as it did at first.
  CameraController fresh(home);
  controller.orbit(0.3, 0.1);
  fresh.orbit(0.3, 0.1);
  EXPECT_TRUE(sameBits(controller.camera(), fresh.camera()));
}

}  // namespace tp::test
