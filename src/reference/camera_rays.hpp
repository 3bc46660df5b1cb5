#pragma once
// The camera's rays as the CPU tracers cast them: through a point of the
// image (pixels from the top-left corner), from the near plane on, as the
// raster's projection maps them; and the frame they fill.
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>

#include "render/renderer.hpp"

#include "shared/frame.h"
#include "shared/haze.h"

namespace tp::render {

struct CameraRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit
};

class CameraRays {
 public:
  CameraRays(const shader::FrameUniforms& uniforms, glm::vec3 eye, uint32_t width, uint32_t height)
      : inverseViewProjection_(uniforms.inverseViewProjection),
        eye_(eye),
        width_(float(width)),
        height_(float(height)) {}

  CameraRay at(float px, float py) const {
    const glm::vec2 ndc(2.0f * px / width_ - 1.0f, 2.0f * py / height_ - 1.0f);
    const glm::vec4 nearPoint = inverseViewProjection_ * glm::vec4(ndc, 0.0f, 1.0f);
    CameraRay ray;
    ray.origin = glm::vec3(nearPoint) / nearPoint.w;
    ray.direction = glm::normalize(ray.origin - eye_);
    return ray;
  }

 private:
  glm::mat4 inverseViewProjection_;
  glm::vec3 eye_;
  float width_, height_;
};

// A frame of the tracers' layout, the camera's matrices set: RGBA 0, no
// normal, and positions and Z at infinity (nothing hit) until filled.
inline RenderedFrame emptyTracedFrame(const shader::FrameUniforms& uniforms, uint32_t width, uint32_t height) {
  RenderedFrame f;
  f.width = width;
  f.height = height;
  f.worldToCamera = uniforms.view;
  f.worldToNDC = uniforms.viewProjection;
  const size_t pixels = size_t(width) * height;
  f.rgba.assign(pixels * 4, 0.0f);
  f.normal.assign(pixels * 4, 0.0f);
  f.position.assign(pixels * 4, std::numeric_limits<float>::infinity());
  return f;
}

// What a camera ray along unit `dir` brings through the air's haze
// (shared/haze.h): `radiance` from the first surface met `distance` metres
// away, or from the sky when nothing was met (infinite distance), which the
// haze hides below the horizon; `horizon(across)` the sky at the horizon
// direction the haze takes its light from. As it is without haze.
template <typename Horizon>
glm::vec3 seenThroughHaze(glm::vec3 radiance, glm::vec3 dir, float distance, float hazeDistance, Horizon horizon) {
  if (hazeDistance <= 0.0f) return radiance;
  const glm::vec3 light = horizon(shader::hazeHorizonDirection(dir));
  if (!std::isfinite(distance)) return dir.y < 0.0f ? light : radiance;
  return shader::hazed(radiance, light, distance, hazeDistance);
}

}  // namespace tp::render
