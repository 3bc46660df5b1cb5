#include "render/env_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shared/env_sampling.h"

namespace tp::render {

namespace {

// The piece of a CDF (n + 1 entries, nondecreasing, 0 to 1) that holds x, and
// how far across it x lies. A piece of zero probability is never returned.
std::pair<uint32_t, float> invertCdf(const double* cdf, uint32_t n, double x) {
  const double* after = std::upper_bound(cdf, cdf + n + 1, x);
  const uint32_t k = std::min<uint32_t>(uint32_t(std::max<ptrdiff_t>(after - cdf - 1, 0)), n - 1);
  const double width = cdf[k + 1] - cdf[k];
  const float f = width > 0.0 ? float(std::clamp((x - cdf[k]) / width, 0.0, 1.0)) : 0.5f;
  return {k, f};
}

}  // namespace

glm::uvec2 equirectTexel(glm::vec3 d, uint32_t width, uint32_t height) {
  const glm::vec2 uv = shader::directionToEquirect(d);
  const uint32_t i = std::min(uint32_t(std::max(uv.x, 0.0f) * float(width)), width - 1);
  const uint32_t j = std::min(uint32_t(std::max(uv.y, 0.0f) * float(height)), height - 1);
  return {i, j};
}

EnvSampler::EnvSampler(const SkyImage& image)
    : width_(image.width),
      height_(image.height),
      luminance_(image.texels.size()),
      rowCdf_(height_ + 1, 0.0),
      columnCdf_(size_t(height_) * (width_ + 1), 0.0) {
  // Sums in double: the CDFs of a 2048 x 1024 map are then exact to float.
  for (uint32_t j = 0; j < height_; ++j) {
    const double omega = shader::envTexelSolidAngle(j, width_, height_);
    double* row = &columnCdf_[size_t(j) * (width_ + 1)];
    for (uint32_t i = 0; i < width_; ++i) {
      const float l = std::max(shader::envLuminance(glm::vec3(image.texels[size_t(j) * width_ + i])), 0.0f);
      luminance_[size_t(j) * width_ + i] = l;
      row[i + 1] = row[i] + l;
    }
    const double rowSum = row[width_];
    if (rowSum > 0.0) {
      for (uint32_t i = 1; i <= width_; ++i) row[i] /= rowSum;
    }
    rowCdf_[j + 1] = rowCdf_[j] + rowSum * omega;
  }
  integral_ = rowCdf_[height_];
  if (!(integral_ > 0.0)) throw std::invalid_argument("an environment to importance-sample needs a positive luminance");
  for (double& c : rowCdf_) c /= integral_;
}

EnvSample EnvSampler::sample(glm::vec2 xi) const {
  const auto [j, fv] = invertCdf(rowCdf_.data(), height_, xi.x);
  const auto [i, fu] = invertCdf(&columnCdf_[size_t(j) * (width_ + 1)], width_, xi.y);
  const glm::uvec2 texel(i, j);
  const glm::vec3 d = shader::envTexelDirection(texel, glm::vec2(fu, fv), glm::uvec2(width_, height_));
  return {d, float(luminance_[size_t(j) * width_ + i] / integral_), texel};
}

glm::uvec2 EnvSampler::texelOf(glm::vec3 d) const { return equirectTexel(d, width_, height_); }

float EnvSampler::pdf(glm::vec3 d) const {
  const glm::uvec2 t = texelOf(d);
  return float(luminance_[size_t(t.y) * width_ + t.x] / integral_);
}

}  // namespace tp::render
