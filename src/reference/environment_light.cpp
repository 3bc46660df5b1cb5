#include "reference/environment_light.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "shading/sky_model.hpp"
#include "shared/env_sampling.h"

namespace tp::render {
namespace {

// The procedural sky is tabulated for the sampler at this width (half as
// high): its smooth gradients and glow need no more; the radiance itself is
// always the exact function.
constexpr uint32_t kProceduralTableWidth = 512;

// The index of the first entry of the increasing `cdf` (size n + 1, from 0)
// above u times its last, and the fraction of the way across that entry.
uint32_t pickFrom(const float* cdf, uint32_t n, float u, float& fraction) {
  const float target = u * cdf[n];
  const uint32_t i = uint32_t(std::upper_bound(cdf + 1, cdf + n, target) - (cdf + 1));
  const float width = cdf[i + 1] - cdf[i];
  fraction = width > 0.0f ? std::clamp((target - cdf[i]) / width, 0.0f, 1.0f) : 0.5f;
  return std::min(i, n - 1);
}

}  // namespace

EnvironmentLight::EnvironmentLight(const scene::Scene& scene) : params_(skyParams(scene.sky)) {
  if (!scene.sky.image.empty()) {
    image_ = loadSkyImage(scene.sky);
    width_ = image_->width;
    height_ = image_->height;
  } else {
    width_ = kProceduralTableWidth;
    height_ = kProceduralTableWidth / 2;
    toSun_ = glm::vec3(params_.sunDirection);
    cosSunRadius_ = params_.sunDirection.w;
    // The disc's radiance as the sky function adds it (above the horizon blend).
    sunRadiance_ = shader::skyRadiance(params_, toSun_, 1.0f) - shader::skyRadiance(params_, toSun_, 0.0f);
    hasSun_ = cosSunRadius_ < 1.0f && glm::dot(sunRadiance_, glm::vec3(1.0f)) > 0.0f;
    sunPdf_ = hasSun_ ? 1.0f / (glm::two_pi<float>() * (1.0f - cosSunRadius_)) : 0.0f;
  }
  texelWeight_.resize(size_t(width_) * height_);
  rowCdf_.assign(size_t(height_) * (width_ + 1), 0.0f);
  marginalCdf_.assign(height_ + 1, 0.0f);
  for (uint32_t j = 0; j < height_; ++j) {
    const float solidAngle = shader::envTexelSolidAngle(j, width_, height_);
    float* cdf = &rowCdf_[size_t(j) * (width_ + 1)];
    for (uint32_t i = 0; i < width_; ++i) {
      glm::vec3 radiance;
      if (image_) {
        radiance = glm::vec3(image_->texels[size_t(j) * width_ + i]);
      } else {
        const glm::vec2 uv((i + 0.5f) / float(width_), (j + 0.5f) / float(height_));
        radiance = shader::skyRadiance(params_, shader::equirectToDirection(uv), 0.0f);
      }
      // The brightest channel: no colour the sky has goes undrawn.
      const float w = std::max({radiance.r, radiance.g, radiance.b, 0.0f}) * solidAngle;
      texelWeight_[size_t(j) * width_ + i] = w;
      cdf[i + 1] = cdf[i] + w;
    }
    marginalCdf_[j + 1] = marginalCdf_[j] + cdf[width_];
  }
  total_ = marginalCdf_[height_];
}

glm::vec3 EnvironmentLight::sky(glm::vec3 d) const {
  return image_ ? skyImageRadiance(*image_, d) : shader::skyRadiance(params_, d, 0.0f);
}

glm::vec3 EnvironmentLight::sun(glm::vec3 d) const {
  return hasSun_ && glm::dot(d, toSun_) >= cosSunRadius_ ? sunRadiance_ : glm::vec3(0.0f);
}

LightSample EnvironmentLight::sampleSky(glm::vec2 u) const {
  if (total_ <= 0.0f) return {};
  glm::vec2 f;
  const uint32_t j = pickFrom(marginalCdf_.data(), height_, u.y, f.y);
  const uint32_t i = pickFrom(&rowCdf_[size_t(j) * (width_ + 1)], width_, u.x, f.x);
  LightSample s;
  s.direction = shader::envTexelDirection(glm::uvec2(i, j), f, glm::uvec2(width_, height_));
  s.radiance = sky(s.direction);
  s.pdf = texelWeight_[size_t(j) * width_ + i] / (total_ * shader::envTexelSolidAngle(j, width_, height_));
  return s;
}

float EnvironmentLight::skyPdf(glm::vec3 d) const {
  if (total_ <= 0.0f) return 0.0f;
  const glm::uvec2 t = shader::envTexelOf(d, glm::uvec2(width_, height_));
  return texelWeight_[size_t(t.y) * width_ + t.x] / (total_ * shader::envTexelSolidAngle(t.y, width_, height_));
}

LightSample EnvironmentLight::sampleSun(glm::vec2 u) const {
  if (!hasSun_) return {};
  const float cosAngle = 1.0f - u.x * (1.0f - cosSunRadius_);
  const float sinAngle = std::sqrt(std::max(0.0f, 1.0f - cosAngle * cosAngle));
  const float phi = glm::two_pi<float>() * u.y;
  const glm::vec3 helper = std::abs(toSun_.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 t = glm::normalize(glm::cross(helper, toSun_)), b = glm::cross(toSun_, t);
  LightSample s;
  s.direction = glm::normalize(cosAngle * toSun_ + sinAngle * (std::cos(phi) * t + std::sin(phi) * b));
  s.radiance = sunRadiance_;
  s.pdf = sunPdf_;
  return s;
}

}  // namespace tp::render
