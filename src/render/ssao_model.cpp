#include "render/ssao_model.hpp"

#include <glm/gtc/constants.hpp>

#include "render/hammersley.hpp"

namespace tp::render {

shader::SsaoKernel ssaoKernel(const scene::Ao& ao) {
  shader::SsaoKernel k{};
  const uint32_t n = ao.kernelSize;
  for (uint32_t i = 0; i < n; ++i) {
    const float t = (float(i) + 0.5f) / float(n);
    const glm::vec3 direction = cosineHemisphere(glm::vec2(radicalInverse(i), radicalInverse3(i)));
    k.samples[i] = glm::vec4(direction * glm::mix(0.1f, 1.0f, t * t), 0.0f);
  }
  const uint32_t texels = ao.noiseSize * ao.noiseSize;
  for (uint32_t i = 0; i < texels; ++i) {
    const float angle = glm::two_pi<float>() * radicalInverse(i);
    k.noise[i] = glm::vec4(std::cos(angle), std::sin(angle), 0.0f, 0.0f);
  }
  return k;
}

shader::SsaoParams ssaoParams(const scene::Ao& ao, uint32_t width, uint32_t height) {
  return {glm::uvec4(ao.kernelSize, ao.noiseSize, width, height), glm::vec4(ao.radius, ao.bias, 0.0f, 0.0f)};
}

shader::AoBlurParams aoBlurParams(const scene::Ao& ao, uint32_t direction, uint32_t width, uint32_t height) {
  return {glm::uvec4(direction, ao.blurTaps, ao.blur == "bilateral" ? 1u : 0u, 0u),
          glm::ivec4(-int(ao.blurTaps / 2), 0, 0, 0), glm::uvec4(width, height, 0u, 0u),
          glm::vec4(ao.blurDepthTolerance, 0.0f, 0.0f, 0.0f)};
}

}  // namespace tp::render
