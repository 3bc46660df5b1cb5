#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "render/sky_image.hpp"

namespace tp::render {

// G(r) of shared/glossy.h computed on the CPU for any direction and exponent:
// the quadrature of the normalised lobe over the environment's texels (each
// piecewise constant, as the GPU prefilter reads them), in double. Each texel
// is split into m x m cells, equal in u and cos(theta) and so in solid angle,
// the lobe taken at their centres: m = ceil(4 sqrt(e) texel width) (at most
// 8) puts 4 cells across the lobe's width at least. Texels where the lobe is
// below kGlossyTruncation of its peak are left out: their share of the lobe
// is at most that, so G is off by at most that times the brightest texel.
// The reference tracer's glossy light, and the prefilter's tests' answer.
class GlossyQuadrature {
 public:
  explicit GlossyQuadrature(const SkyImage& sky) : sky_(sky) {}
  glm::dvec3 radiance(glm::vec3 r, float exponent) const;

 private:
  const SkyImage& sky_;
};

// The share of the lobe, relative to its peak, below which texels are left out.
constexpr double kGlossyTruncation = 1e-8;

// How far estimates of a prefiltered level are from the exact values at the
// same texels: the RMS of the differences relative to the mean exact value,
// and the worst difference relative to the brightest (the prefilter's tests
// and bench ibl's glossy table).
struct GlossyLevelError {
  double rms = 0.0;
  double worst = 0.0;
};
GlossyLevelError glossyLevelError(const std::vector<double>& estimate, const std::vector<double>& exact);

}  // namespace tp::render
