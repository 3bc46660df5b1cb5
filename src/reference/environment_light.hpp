#pragma once
// The light from beyond the scene for the path tracer: the sky's radiance
// function (the procedural sky's, or the scene's image, bilinear as the
// renderer reads it), drawn by importance over its texels, and the
// procedural sky's sun disc as a light of its own, drawn uniformly over its
// cone. Only the radiance functions are shared with the raster; the
// sampling is the tracer's.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "render/sky_image.hpp"
#include "scene/scene.hpp"
#include "shared/sky.h"

namespace tp::render {

struct LightSample {
  glm::vec3 direction{0.0f};  // unit, towards the light
  glm::vec3 radiance{0.0f};
  float pdf = 0.0f;  // per steradian
};

class EnvironmentLight {
 public:
  explicit EnvironmentLight(const scene::Scene& scene);

  // The sky along unit d without the sun's disc (an image sky: all of it).
  glm::vec3 sky(glm::vec3 d) const;
  // The sun's disc along d: its radiance inside the cone, 0 outside or
  // without a procedural sun.
  glm::vec3 sun(glm::vec3 d) const;
  bool hasSun() const { return hasSun_; }
  glm::vec3 sunDirection() const { return toSun_; }

  // A direction drawn from the sky's texels by their brightness times solid
  // angle, u in the unit square; its density, and the density of any d.
  LightSample sampleSky(glm::vec2 u) const;
  float skyPdf(glm::vec3 d) const;
  // A direction drawn uniformly over the sun's cone; its constant density.
  LightSample sampleSun(glm::vec2 u) const;
  float sunPdf() const { return sunPdf_; }

 private:
  std::optional<SkyImage> image_;
  shader::SkyParams params_{};
  bool hasSun_ = false;
  glm::vec3 toSun_{0.0f, 1.0f, 0.0f};
  float cosSunRadius_ = 1.0f;
  glm::vec3 sunRadiance_{0.0f};
  float sunPdf_ = 0.0f;
  // The sampler's piecewise-constant table: width x height texels, the
  // conditional CDF of each row and the marginal CDF over rows.
  uint32_t width_ = 0, height_ = 0;
  std::vector<float> texelWeight_;  // row-major, brightness times solid angle
  std::vector<float> rowCdf_;       // height * (width + 1)
  std::vector<float> marginalCdf_;  // height + 1
  float total_ = 0.0f;
};

}  // namespace tp::render
