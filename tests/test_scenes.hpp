#pragma once
// Scenes for tests whose measures assume them.
//
// The built-in scene with the test scene's surfaces: checkers on the ground
// and on the pool's floor, plain walls, a clear sky and clear air. For tests
// whose exact answers assume surfaces of one albedo each and the light
// reaching the camera unfaded.
#include "scene/scene.hpp"

namespace tp::test {

inline scene::Scene checkerScene() {
  scene::Scene s = scene::defaultScene();
  s.ground.pattern = "checker";
  s.pool.floorPattern = "checker";
  s.pool.wallPattern = "plain";
  s.sky.clouds.coverage = 0.0f;
  s.sky.hazeDistance = 0.0f;
  return s;
}

// The camera closer over the pool than the default scene's, the water
// filling most of the frame: for tests that measure on the water's pixels.
inline scene::Scene overThePool(scene::Scene s) {
  s.camera.position = {3.2f, 2.4f, 4.6f};
  s.camera.target = {0.0f, 0.3f, 0.0f};
  s.camera.fovYDegrees = 50.0f;
  return s;
}

}  // namespace tp::test
