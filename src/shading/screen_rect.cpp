#include "shading/screen_rect.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tp::render {

PixelRect united(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

PixelRect pixelsCovering(const glm::mat4& viewProjection, glm::uvec2 pixels, glm::vec3 lo, glm::vec3 hi) {
  std::array<glm::vec4, 8> clip;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    clip[corner] = viewProjection * glm::vec4(p, 1.0f);
  }
  // Wholly outside one of the frustum's planes (x, y within +-w, 0 <= z <= w): nothing shows.
  auto allOutside = [&](auto outside) { return std::all_of(clip.begin(), clip.end(), outside); };
  if (allOutside([](const glm::vec4& c) { return c.x < -c.w; }) ||
      allOutside([](const glm::vec4& c) { return c.x > c.w; }) ||
      allOutside([](const glm::vec4& c) { return c.y < -c.w; }) ||
      allOutside([](const glm::vec4& c) { return c.y > c.w; }) ||
      allOutside([](const glm::vec4& c) { return c.z < 0.0f; }) ||
      allOutside([](const glm::vec4& c) { return c.z > c.w; })) {
    return {};
  }
  const PixelRect whole{glm::uvec2(0u), pixels};
  glm::vec2 least(INFINITY), most(-INFINITY);
  for (const glm::vec4& c : clip) {
    if (!(c.w > 0.0f)) return whole;
    // In pixel centres: p = (ndc * 0.5 + 0.5) * pixels - 0.5.
    const glm::vec2 at = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(pixels) - 0.5f;
    least = glm::min(least, at);
    most = glm::max(most, at);
  }
  if (!std::isfinite(least.x + least.y + most.x + most.y)) return whole;
  // The pixels whose centres lie in [least, most], one more each side.
  const glm::vec2 size(pixels);
  const glm::vec2 from = glm::clamp(glm::floor(least) - 1.0f, glm::vec2(0.0f), size);
  const glm::vec2 to = glm::clamp(glm::ceil(most) + 2.0f, glm::vec2(0.0f), size);
  return {glm::uvec2(from), glm::uvec2(to)};
}

}  // namespace tp::render
