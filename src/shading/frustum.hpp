#pragma once
#include <array>
#include <glm/glm.hpp>

namespace tp::render {

// The six planes of a Vulkan view frustum (clip space 0 <= z <= w), from its
// world-to-clip matrix (Gribb and Hartmann): a point p is inside where
// dot(plane.xyz, p) + plane.w >= 0 for all six.
class Frustum {
 public:
  explicit Frustum(const glm::mat4& worldToClip);
  // False only when the sphere lies wholly outside one plane: a sphere that
  // may show is never culled (it may be kept when a corner region misses).
  bool mayShow(glm::vec3 center, float radius) const;

 private:
  std::array<glm::vec4, 6> planes_;
};

}  // namespace tp::render
