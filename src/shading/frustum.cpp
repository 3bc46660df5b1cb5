#include "shading/frustum.hpp"

namespace tp::render {

Frustum::Frustum(const glm::mat4& m) {
  const glm::vec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]), row1(m[0][1], m[1][1], m[2][1], m[3][1]),
      row2(m[0][2], m[1][2], m[2][2], m[3][2]), row3(m[0][3], m[1][3], m[2][3], m[3][3]);
  planes_ = {row3 + row0, row3 - row0, row3 + row1, row3 - row1, row2, row3 - row2};
}

bool Frustum::mayShow(glm::vec3 center, float radius) const {
  for (const glm::vec4& plane : planes_) {
    if (glm::dot(glm::vec3(plane), center) + plane.w < -radius * glm::length(glm::vec3(plane))) return false;
  }
  return true;
}

}  // namespace tp::render
