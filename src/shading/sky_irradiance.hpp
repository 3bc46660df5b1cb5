#pragma once
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "shared/sky_irradiance.h"

namespace tp::render {

// The sky's radiance along a unit direction, without the sun's disc.
using SkyRadiance = std::function<glm::vec3(glm::vec3)>;

// The sky above the horizon cut in bins of equal solid angle, for the sums
// over its light: each bin holds the sky's light over it (its mean radiance
// over subsamples times its solid angle) and the direction that light comes
// from on average (weighted by it), so that a blob smaller than a bin still
// brings its light from where it is.
class SkyBins {
 public:
  struct Bin {
    glm::vec3 direction;
    glm::vec3 light;
  };
  // `bands` bands of the cosine from the zenith, `azimuths` of azimuth,
  // `subsamples` squared points a bin.
  SkyBins(const SkyRadiance& sky, uint32_t bands, uint32_t azimuths, uint32_t subsamples);
  const std::vector<Bin>& bins() const { return bins_; }
  // The irradiance the sky gives a surface facing up.
  glm::vec3 irradianceUp() const;

 private:
  std::vector<Bin> bins_;
};

// The irradiance polynomial (shared/sky_irradiance.h) of the light round a
// point in the open: the sky's bins above the horizon and a uniform radiance
// `below` under it (the ground's). A least-squares fit of the irradiance,
// summed exactly over the bins, at normals spread over the sphere: the
// projection onto bands 0-6, the rest of the clamped cosine's series (band 8
// on, under 0.3% of a delta light's) left out.
shader::SkyIrradiance fitSkyIrradiance(const SkyBins& sky, glm::vec3 below);

}  // namespace tp::render
