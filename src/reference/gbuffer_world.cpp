#include "reference/gbuffer_world.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "shared/ssao.h"

namespace tp::render {
namespace {
constexpr float kDepthSteps = 4.0f;
}  // namespace

WorldGbuffer worldGbuffer(const RenderedFrame& frame) {
  const size_t pixels = size_t(frame.width) * frame.height;
  if (frame.gbufferDepth.size() != pixels || frame.gbufferNormal.size() != pixels * 4) {
    throw std::logic_error("worldGbuffer: the frame has no G-buffer (render it with FrameRequest::ao)");
  }
  const glm::mat4 cameraToWorld = glm::inverse(frame.worldToCamera);
  const glm::mat3 normalToWorld(cameraToWorld);  // a rotation: normals transform as positions do
  const float inf = std::numeric_limits<float>::infinity();
  WorldGbuffer out{std::vector<float>(pixels * 4, inf), std::vector<float>(pixels * 4, 0.0f),
                   std::vector<float>(pixels, 0.0f)};
  for (uint32_t y = 0; y < frame.height; ++y) {
    for (uint32_t x = 0; x < frame.width; ++x) {
      const size_t k = size_t(y) * frame.width + x;
      const float depth = frame.gbufferDepth[k];
      if (depth >= 1.0f) continue;
      const glm::vec2 uv((float(x) + 0.5f) / float(frame.width), (float(y) + 0.5f) / float(frame.height));
      const glm::vec3 view = shader::viewPositionFromDepth(frame.inverseProjection, uv, depth);
      const glm::vec3 p = glm::vec3(cameraToWorld * glm::vec4(view, 1.0f));
      const glm::vec3 n = normalToWorld * glm::vec3(frame.gbufferNormal[k * 4], frame.gbufferNormal[k * 4 + 1],
                                                    frame.gbufferNormal[k * 4 + 2]);
      for (int c = 0; c < 3; ++c) {
        out.position[k * 4 + c] = p[c];
        out.normal[k * 4 + c] = n[c];
      }
      out.position[k * 4 + 3] = -view.z;
      // Rasterised depth is within an ulp or two of the true surface's; allow
      // four. In double: in float the step can vanish in the reconstruction.
      const glm::dmat4 inverse(frame.inverseProjection);
      auto at = [&](double d) {
        const glm::dvec4 q = inverse * glm::dvec4(uv.x * 2.0 - 1.0, uv.y * 2.0 - 1.0, d, 1.0);
        return glm::dvec3(q) / q.w;
      };
      const double step = double(std::nextafter(depth, 2.0f)) - double(depth);
      out.uncertainty[k] = float(kDepthSteps * glm::length(at(double(depth) + step) - at(double(depth))));
    }
  }
  return out;
}

}  // namespace tp::render
