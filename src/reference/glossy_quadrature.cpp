#include "reference/glossy_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace tp::render {

glm::dvec3 GlossyQuadrature::radiance(glm::vec3 direction, float exponent) const {
  const glm::dvec3 r = glm::normalize(glm::dvec3(direction));
  const double e = exponent, pi = glm::pi<double>();
  const uint32_t w = sky_.width, h = sky_.height;
  // The cap outside which the lobe is below the truncation: cos^e < t.
  const double capCos = std::pow(kGlossyTruncation, 1.0 / std::max(e, 1e-6));
  const double cap = std::acos(std::clamp(capCos, -1.0, 1.0));
  const double thetaR = std::acos(std::clamp(r.y, -1.0, 1.0));
  const double phiR = std::atan2(r.z, r.x);
  const double texelAngle = pi / h;
  const int m = int(std::clamp(std::ceil(4.0 * std::sqrt(e) * texelAngle), 2.0, 8.0));
  // Rows that meet the cap; in each, the columns within its azimuthal reach
  // (asin(sin cap / sin theta_r) when the cap holds neither pole).
  const int rowFirst = std::max(0, int(std::floor((thetaR - cap) / texelAngle)) - 1);
  const int rowLast = std::min(int(h) - 1, int(std::ceil((thetaR + cap) / texelAngle)) + 1);
  const bool allColumns = cap >= thetaR || cap >= pi - thetaR;
  const double reach = allColumns ? pi : std::asin(std::min(1.0, std::sin(cap) / std::sin(thetaR)));
  const int reachTexels = allColumns ? int(w) : std::min(int(w), int(std::ceil(reach / (2.0 * pi / w))) + 2);
  // Column of phi: u = phi / 2pi + 1/2.
  const int centreColumn = int(std::floor((phiR / (2.0 * pi) + 0.5) * w));
  const double norm = (e + 1.0) / (2.0 * pi);
  glm::dvec3 sum(0.0);
  for (int j = rowFirst; j <= rowLast; ++j) {
    const double cosTop = std::cos(pi * j / h), cosBottom = std::cos(pi * (j + 1) / h);
    const double cellSolidAngle = 2.0 * pi / w * (cosTop - cosBottom) / (m * m);
    const int columns = allColumns ? int(w) : 2 * reachTexels + 1;
    for (int c = 0; c < columns; ++c) {
      const int column = allColumns ? c : centreColumn - reachTexels + c;
      const int i = ((column % int(w)) + int(w)) % int(w);
      const glm::vec4 texel = sky_.texels[size_t(j) * w + size_t(i)];
      if (texel.r == 0.0f && texel.g == 0.0f && texel.b == 0.0f) continue;
      double weight = 0.0;
      for (int a = 0; a < m; ++a) {
        const double cosTheta = cosTop + (cosBottom - cosTop) * (a + 0.5) / m;
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        for (int b = 0; b < m; ++b) {
          const double phi = ((i + (b + 0.5) / m) / w - 0.5) * 2.0 * pi;
          const double cosAngle = sinTheta * std::cos(phi) * r.x + cosTheta * r.y + sinTheta * std::sin(phi) * r.z;
          if (cosAngle > 0.0) weight += std::pow(cosAngle, e);
        }
      }
      sum += glm::dvec3(texel) * (weight * norm * cellSolidAngle);
    }
  }
  return sum;
}

GlossyLevelError glossyLevelError(const std::vector<double>& estimate, const std::vector<double>& exact) {
  double squares = 0.0, sum = 0.0, peak = 0.0, worst = 0.0;
  for (size_t t = 0; t < exact.size(); ++t) {
    const double difference = estimate[t] - exact[t];
    squares += difference * difference;
    sum += exact[t];
    peak = std::max(peak, exact[t]);
    worst = std::max(worst, std::abs(difference));
  }
  const double n = double(exact.size());
  return {std::sqrt(squares / n) / (sum / n), worst / peak};
}

}  // namespace tp::render
