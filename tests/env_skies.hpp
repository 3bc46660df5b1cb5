#pragma once
// Environments for the image-based lighting tests.
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "render/sky_image.hpp"
#include "shared/equirect.h"

namespace tp::test {

// A w x h grey sky of radiance `background` with a disc of radius 3 degrees,
// 40 degrees up, of radiance `disc` (a sun): a peaked environment.
inline render::SkyImage discSky(uint32_t w, uint32_t h, float background, float disc) {
  render::SkyImage image{w, h, std::vector<glm::vec4>(size_t(w) * h, glm::vec4(glm::vec3(background), 1.0f))};
  const float elevation = glm::radians(40.0f);
  const glm::vec3 centre(std::cos(elevation), std::sin(elevation), 0.0f);
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      const glm::vec3 d = shader::equirectToDirection({(i + 0.5f) / w, (j + 0.5f) / h});
      if (glm::dot(d, centre) > std::cos(glm::radians(3.0f)))
        image.texels[size_t(j) * w + i] = glm::vec4(glm::vec3(disc), 1.0f);
    }
  }
  return image;
}

}  // namespace tp::test
