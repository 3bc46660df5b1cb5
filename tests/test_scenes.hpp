#pragma once
// Scenes for tests whose measures assume them.
//
// The built-in scene with the test scene's surfaces: checkers on the ground
// and on the pool's floor, plain walls, a clear sky and clear air. For tests
// whose exact answers assume surfaces of one albedo each and the light
// reaching the camera unfaded.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

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

// The camera scenes/glossy.json sees its pool with, the far walls above the
// water in view.
inline scene::Scene asGlossySeesThePool(scene::Scene s) {
  s.camera.position = {2.6f, 1.5f, 3.4f};
  s.camera.target = {-0.2f, -0.4f, -0.4f};
  s.camera.fovYDegrees = 55.0f;
  return s;
}

// The pixels whose first surface (`position`, an AOV of xyzw per pixel) is
// one of `s`'s pool walls above the water, `margin` metres and more from the
// rim and the water.
inline std::vector<uint8_t> wallsAboveTheWater(const std::vector<float>& position, const scene::Scene& s,
                                               float margin) {
  const float half = 0.5f * s.water.extent;
  std::vector<uint8_t> walls(position.size() / 4, 0);
  for (size_t k = 0; k < walls.size(); ++k) {
    const float x = position[k * 4], y = position[k * 4 + 1], z = position[k * 4 + 2];
    walls[k] = std::abs(half - std::max(std::abs(x), std::abs(z))) < 1e-3f && y > s.water.level + margin &&
               y < s.ground.height - margin;
  }
  return walls;
}

}  // namespace tp::test
