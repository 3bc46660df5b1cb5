// A moving camera (scene/camera.cpp cameraAt): keyframes, linear or
// Catmull-Rom between them, and the turntable, against closed forms; and a
// frame of a sequence against the still camera it should be.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "io/image_io.hpp"
#include "process.hpp"
#include "scene/camera.hpp"

namespace tp::test {
namespace {

scene::CameraKeyframe key(float time, glm::vec3 position, glm::vec3 target, float fov) {
  return {time, position, target, fov};
}

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << what << " component " << c;
}

scene::Camera pathCamera(const std::string& interpolation) {
  scene::Camera c;
  c.interpolation = interpolation;
  c.path = {key(0.0f, {4, 2, 0}, {0, 0, 0}, 40), key(1.0f, {0, 3, 4}, {0, 1, 0}, 50),
            key(3.0f, {-4, 2, 1}, {1, 0, 0}, 30), key(4.0f, {-1, 5, -3}, {0, 0, 1}, 60)};
  return c;
}

}  // namespace

TEST(CameraPath, KeysAreHitAndHeldAtTheEnds) {
  for (const char* interpolation : {"linear", "catmull_rom"}) {
    const scene::Camera c = pathCamera(interpolation);
    scene::validateCamera(c);
    for (const auto& k : c.path) {
      const scene::Camera at = scene::cameraAt(c, k.time);
      expectNear(at.position, k.position, 1e-5f, interpolation);
      expectNear(at.target, k.target, 1e-5f, interpolation);
      EXPECT_NEAR(at.fovYDegrees, k.fovYDegrees, 1e-4f) << interpolation;
    }
    expectNear(scene::cameraAt(c, -2.0f).position, c.path.front().position, 0.0f, "before");
    expectNear(scene::cameraAt(c, 9.0f).position, c.path.back().position, 0.0f, "after");
  }
  // Halfway between two keys, a straight line is at their mean.
  const scene::Camera linear = pathCamera("linear");
  const scene::Camera mid = scene::cameraAt(linear, 2.0f);
  expectNear(mid.position, 0.5f * (linear.path[1].position + linear.path[2].position), 1e-5f, "mid position");
  EXPECT_NEAR(mid.fovYDegrees, 40.0f, 1e-4f);
}

// Catmull-Rom reproduces a straight line at constant speed between inner
// keys, and its velocity has no jump at a key (the straight path's does).
TEST(CameraPath, CatmullRomIsExactOnALineAndSmoothAtKeys) {
  scene::Camera line;
  line.interpolation = "catmull_rom";
  const glm::vec3 step(0.5f, 0.25f, -1.0f);
  for (int k = 0; k < 4; ++k) line.path.push_back(key(float(k), glm::vec3(1, 2, 3) + float(k) * step, {0, 0, 0}, 50));
  for (const float t : {1.0f, 1.3f, 1.5f, 1.9f}) {
    expectNear(scene::cameraAt(line, t).position, glm::vec3(1, 2, 3) + t * step, 1e-5f, "t " + std::to_string(t));
  }
  // One-sided second-order differences: their error is h^2 times the jerk.
  const auto velocityJump = [](const scene::Camera& c, float t) {
    const float h = 1e-2f;
    const auto p = [&](float u) { return scene::cameraAt(c, u).position; };
    const glm::vec3 before = (3.0f * p(t) - 4.0f * p(t - h) + p(t - 2.0f * h)) / (2.0f * h);
    const glm::vec3 after = (-3.0f * p(t) + 4.0f * p(t + h) - p(t + 2.0f * h)) / (2.0f * h);
    return glm::length(after - before);
  };
  // Keys one second apart on each side of t = 1, so the spline's uniform parameter is time.
  scene::Camera curve = pathCamera("catmull_rom");
  curve.path[2].time = 2.0f;
  curve.path[3].time = 3.0f;
  EXPECT_LT(velocityJump(curve, 1.0f), 0.05f);
  scene::Camera straight = curve;
  straight.interpolation = "linear";
  EXPECT_GT(velocityJump(straight, 1.0f), 1.0f);
}

TEST(CameraPath, TurntableTurnsAboutTheTargetsVertical) {
  scene::Camera c;
  c.position = {3, 2, 0};
  c.target = {1, 0.5f, 0};
  c.turntableSeconds = 8.0f;
  scene::validateCamera(c);
  // A quarter turn takes +x to +z about the target; a whole turn comes back.
  expectNear(scene::cameraAt(c, 2.0f).position, {1, 2, 2}, 1e-5f, "quarter");
  expectNear(scene::cameraAt(c, 4.0f).position, {-1, 2, 0}, 1e-5f, "half");
  expectNear(scene::cameraAt(c, 8.0f).position, c.position, 1e-5f, "whole");
  expectNear(scene::cameraAt(c, 3.0f).target, c.target, 0.0f, "target");
  for (const float t : {0.7f, 5.1f, 100.3f}) {
    const scene::Camera at = scene::cameraAt(c, t);
    EXPECT_NEAR(glm::length(at.position - at.target), glm::length(c.position - c.target), 1e-4f) << t;
    EXPECT_FLOAT_EQ(at.position.y, c.position.y) << t;
  }
  EXPECT_EQ(scene::cameraAt(scene::Camera{}, 5.0f), scene::Camera{});  // a still camera stands
}

TEST(CameraPath, ImpossiblePathsAreRefused) {
  scene::Camera c = pathCamera("linear");
  c.path[2].time = 0.5f;  // before the key ahead of it
  EXPECT_THROW(scene::validateCamera(c), std::runtime_error);
  c = pathCamera("cubic");
  EXPECT_THROW(scene::validateCamera(c), std::runtime_error);
  c = pathCamera("linear");
  c.turntableSeconds = 4.0f;
  EXPECT_THROW(scene::validateCamera(c), std::runtime_error);
  c = pathCamera("linear");
  c.path[1].target = c.path[1].position;
  EXPECT_THROW(scene::validateCamera(c), std::runtime_error);
  c = pathCamera("linear");
  c.path[3].fovYDegrees = 180.0f;
  EXPECT_THROW(scene::validateCamera(c), std::runtime_error);
  scene::Camera spin;
  spin.turntableSeconds = -1.0f;
  EXPECT_THROW(scene::validateCamera(spin), std::runtime_error);
}

// Frame 1 of a sequence whose camera path reaches a key at frame 1 is, bit
// for bit, the frame a still camera at that key renders; frame 0 is not.
TEST(CameraPath, SequenceFramesFollowThePath) {
  ScratchDir dir;
  // frame_time 0.0333333333: the second key at 1/30 s is frame 1.
  writeText(dir.file("moving.json"), R"({"camera": {"path": [
      {"time": 0, "position": [3.2, 2.4, 4.6], "target": [0, 0.3, 0], "fov": 50},
      {"time": 0.0333333333, "position": [-2.5, 1.5, 4.0], "target": [0.2, 0.0, -0.3], "fov": 38}]},
      "water": {"grid": 64}})");
  writeText(dir.file("still.json"), R"({"camera": {"position": [-2.5, 1.5, 4.0], "target": [0.2, 0.0, -0.3],
      "fov": 38}, "water": {"grid": 64}})");
  const std::string common = "render --size 48x32 --validate";
  ProcessResult r =
      runTidepool(common + " --scene " + dir.file("moving.json") + " --frames 0-1 --out " + dir.file("m.#.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runTidepool(common + " --scene " + dir.file("still.json") + " --frame 1 --out " + dir.file("s.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runTidepool(common + " --scene " + dir.file("moving.json") + " --frame 1 --out " + dir.file("one.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const io::FloatImage m0 = io::readImage(dir.file("m.0.exr")), m1 = io::readImage(dir.file("m.1.exr")),
                       still = io::readImage(dir.file("s.exr")), one = io::readImage(dir.file("one.exr"));
  ASSERT_EQ(m1.pixels.size(), still.pixels.size());
  EXPECT_EQ(0, std::memcmp(m1.pixels.data(), still.pixels.data(), m1.pixels.size() * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(one.pixels.data(), still.pixels.data(), one.pixels.size() * sizeof(float)));
  EXPECT_NE(0, std::memcmp(m0.pixels.data(), still.pixels.data(), m0.pixels.size() * sizeof(float)));
}

}  // namespace tp::test
