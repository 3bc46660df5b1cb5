#include "shading/grid_detail.hpp"

#include <algorithm>
#include <array>

namespace tp::render {

uint32_t gridStep(const glm::mat4& viewProjection, glm::vec2 pixels, glm::vec3 centre, float extent,
                  uint32_t vertices) {
  if (vertices < 2) return 1;
  const float h = 0.5f * extent;
  const std::array<glm::vec3, 4> corners{centre + glm::vec3(-h, 0.0f, -h), centre + glm::vec3(h, 0.0f, -h),
                                         centre + glm::vec3(h, 0.0f, h), centre + glm::vec3(-h, 0.0f, h)};
  std::array<glm::vec2, 4> projected{};
  for (size_t k = 0; k < corners.size(); ++k) {
    const glm::vec4 clip = viewProjection * glm::vec4(corners[k], 1.0f);
    if (!(clip.w > 0.0f)) return 1;
    projected[k] = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * pixels;
  }
  float longest = 0.0f;
  for (size_t k = 0; k < projected.size(); ++k) {
    longest = std::max(longest, glm::distance(projected[k], projected[(k + 1) % projected.size()]));
  }
  const float quadPixels = longest / float(vertices - 1);
  uint32_t step = 1;
  while (step * 2 <= kMaxGridStep && float(step * 2) * quadPixels <= kMaxQuadPixels) step *= 2;
  return step;
}

}  // namespace tp::render
