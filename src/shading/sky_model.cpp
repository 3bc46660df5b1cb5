#include "shading/sky_model.hpp"

#include <glm/gtc/constants.hpp>
#include <stdexcept>

namespace tp::render {

uint32_t noiseKind(const std::string& name) {
  if (name == "value") return TP_NOISE_VALUE_BILINEAR;
  if (name == "value_cubic") return TP_NOISE_VALUE_CUBIC;
  if (name == "gradient") return TP_NOISE_GRADIENT;
  if (name == "simplex") return TP_NOISE_SIMPLEX;
  throw std::invalid_argument("unknown noise '" + name + "'");
}

glm::vec3 sunDirection(const scene::Sky& sky) {
  const float elevation = glm::radians(sky.sunElevationDegrees);
  const float azimuth = glm::radians(sky.sunAzimuthDegrees);
  return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth)};
}

shader::SkyParams skyParams(const scene::Sky& sky) {
  const scene::Clouds& c = sky.clouds;
  shader::SkyParams p{};
  p.zenith = glm::vec4(sky.zenith, sky.zenithExponent);
  p.horizon = glm::vec4(sky.horizon, sky.horizonBlend);
  p.ground = glm::vec4(sky.ground, c.scale);
  p.sunDirection = glm::vec4(sunDirection(sky), std::cos(glm::radians(sky.sunAngularRadiusDegrees)));
  p.sunRadiance = glm::vec4(sky.sunRadiance, c.persistence);
  p.glow = glm::vec4(sky.glow, sky.glowExponent);
  p.cloudColor = glm::vec4(c.color, c.coverage);
  p.counts = glm::uvec4(sky.textureWidth, noiseKind(c.noise), c.seed, c.octaves);
  return p;
}

glm::vec3 sunIrradiance(const scene::Sky& sky) {
  const float solidAngle = glm::two_pi<float>() * (1.0f - std::cos(glm::radians(sky.sunAngularRadiusDegrees)));
  return sky.sunRadiance * solidAngle;
}

shader::Sh9 skySh9(const scene::Sky& sky) {
  // Midpoint rule in (theta, phi) over the upper hemisphere; the sky is smooth
  // apart from the sun disk, which is left out here and lit separately.
  constexpr int kTheta = 128, kPhi = 256;
  const shader::SkyParams p = skyParams(sky);
  const double dTheta = glm::half_pi<double>() / kTheta, dPhi = glm::two_pi<double>() / kPhi;
  glm::dvec3 sum[9] = {};
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * dTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * dPhi;
      glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      const glm::dvec3 weighted = glm::dvec3(shader::skyRadiance(p, d, 0.0f)) * std::sin(theta) * dTheta * dPhi;
      for (uint32_t k = 0; k < 9; ++k) sum[k] += weighted * double(shader::sh9Basis(k, d));
    }
  }
  shader::Sh9 sh{};
  for (int k = 0; k < 9; ++k) sh.c[k] = glm::vec4(glm::vec3(sum[k]), 0.0f);
  return sh;
}

SkyLight proceduralSkyLight(const scene::Sky& sky) {
  return SkyLight{sunDirection(sky), sunIrradiance(sky), skySh9(sky)};
}

}  // namespace tp::render
