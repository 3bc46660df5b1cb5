#include "shading/ssao_model.hpp"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>

#include "shading/hammersley.hpp"

namespace tp::render {
namespace {

void hammersleyPattern(const scene::Ao& ao, shader::SsaoKernel& k) {
  const uint32_t n = ao.kernelSize;
  for (uint32_t i = 0; i < n; ++i) {
    const float t = (float(i) + 0.5f) / float(n);
    const glm::vec3 direction = cosineHemisphere(glm::vec2(radicalInverse(i), radicalInverseBase(i, 3)));
    k.samples[i] = glm::vec4(direction * glm::mix(0.1f, 1.0f, t * t), 0.0f);
  }
  for (uint32_t i = 0; i < ao.noiseSize * ao.noiseSize; ++i) {
    const float angle = glm::two_pi<float>() * radicalInverse(i);
    k.noise[i] = glm::vec4(std::cos(angle), std::sin(angle), 0.0f, 0.0f);
  }
}

void randomPattern(const scene::Ao& ao, shader::SsaoKernel& k) {
  std::mt19937 engine(0u);  // its output sequence is fixed by the standard, unlike the distributions'
  auto r = [&] { return float(engine() >> 8) * 0x1p-24f; };
  const uint32_t n = ao.kernelSize;
  for (uint32_t i = 0; i < n; ++i) {
    const float x = r() * 2.0f - 1.0f, y = r() * 2.0f - 1.0f, z = r();
    glm::vec3 sample = glm::vec3(x, y, z);
    const float length = glm::length(sample);
    sample = length > 0.0f ? sample / length : glm::vec3(0.0f, 0.0f, 1.0f);
    const float scale = float(i) / float(n);
    k.samples[i] = glm::vec4(sample * r() * glm::mix(0.1f, 1.0f, scale * scale), 0.0f);
  }
  for (uint32_t i = 0; i < ao.noiseSize * ao.noiseSize; ++i) {
    const float x = r() * 2.0f - 1.0f, y = r() * 2.0f - 1.0f;
    k.noise[i] = glm::vec4(x, y, 0.0f, 0.0f);
  }
}

}  // namespace

shader::SsaoKernel ssaoKernel(const scene::Ao& ao) {
  shader::SsaoKernel k{};
  if (ao.pattern == "random") {
    randomPattern(ao, k);
  } else {
    hammersleyPattern(ao, k);
  }
  return k;
}

uint32_t aoFactor(const scene::Ao& ao) { return ao.resolution == "half" ? 2u : 1u; }

vk::Extent2D aoExtent(const scene::Ao& ao, uint32_t width, uint32_t height) {
  const uint32_t f = aoFactor(ao);
  return {(width + f - 1) / f, (height + f - 1) / f};
}

shader::SsaoParams ssaoParams(const scene::Ao& ao, uint32_t width, uint32_t height) {
  const vk::Extent2D e = aoExtent(ao, width, height);
  return {glm::uvec4(ao.kernelSize, ao.noiseSize, aoFactor(ao), ao.depthLookup == "interpolated" ? 1u : 0u),
          glm::uvec4(e.width, e.height, width, height), glm::vec4(ao.radius, ao.bias, 0.0f, 0.0f)};
}

shader::AoBlurParams aoBlurParams(const scene::Ao& ao, uint32_t direction, uint32_t width, uint32_t height) {
  const vk::Extent2D e = aoExtent(ao, width, height);
  return {glm::uvec4(direction, ao.blurTaps, ao.blur == "bilateral" ? 1u : 0u, 0u),
          glm::ivec4(-int(ao.blurTaps / 2), 0, 0, 0), glm::uvec4(e.width, e.height, 0u, 0u),
          glm::vec4(ao.blurDepthTolerance, 0.0f, 0.0f, 0.0f)};
}

shader::AoUpsampleParams aoUpsampleParams(const scene::Ao& ao, uint32_t width, uint32_t height) {
  const vk::Extent2D e = aoExtent(ao, width, height);
  return {glm::uvec4(width, height, e.width, e.height),
          glm::vec4(ao.blurDepthTolerance, float(aoFactor(ao)), 0.0f, 0.0f)};
}

}  // namespace tp::render
