#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "render/sky_image.hpp"

namespace tp::render {

// One direction drawn from an environment: its solid-angle density and texel.
struct EnvSample {
  glm::vec3 direction;
  float pdf;  // per steradian
  glm::uvec2 texel;
};

// Importance sampling of an equirectangular environment by its luminance
// (shaders_glsl/shared/env_sampling.h): a marginal CDF over the rows and a
// conditional CDF over each row's texels, inverted continuously.
class EnvSampler {
 public:
  // Throws when the image has no positive luminance to sample.
  explicit EnvSampler(const SkyImage& image);

  // The direction for a point xi of the unit square (xi.x picks the row).
  EnvSample sample(glm::vec2 xi) const;
  // The solid-angle density of drawing direction d.
  float pdf(glm::vec3 d) const;
  // The texel holding direction d.
  glm::uvec2 texelOf(glm::vec3 d) const;
  // The integral of the luminance over the sphere (the density's normalisation).
  double luminanceIntegral() const { return integral_; }

  // The CDFs, as documented at the members.
  const std::vector<double>& rowCdf() const { return rowCdf_; }
  const std::vector<double>& columnCdf() const { return columnCdf_; }

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  uint32_t width_, height_;
  std::vector<float> luminance_;   // per texel, rows top to bottom
  std::vector<double> rowCdf_;     // height + 1 entries, 0 to 1
  std::vector<double> columnCdf_;  // per row, width + 1 entries, 0 to 1 (all 0 for a row of no weight)
  double integral_ = 0.0;
};

// The texel of an equirectangular image holding direction d (nearest: the
// piecewise-constant environment the sampler and the projection describe).
glm::uvec2 equirectTexel(glm::vec3 d, uint32_t width, uint32_t height);

}  // namespace tp::render
