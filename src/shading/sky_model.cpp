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

}  // namespace tp::render
