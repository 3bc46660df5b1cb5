#include "shading/sky_irradiance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace tp::render {
namespace {

// Normals the fit takes the irradiance at: a Fibonacci lattice over the
// sphere, many more than the polynomial's 31 terms, so that the least
// squares are the projection onto its bands.
constexpr uint32_t kFitNormals = 1024;

using Terms = std::array<double, shader::kSkyIrradianceTerms>;

// The polynomial's terms at n: skyIrradianceSum with one coefficient 1.
Terms termsAt(glm::vec3 n) {
  Terms t{};
  for (int k = 0; k < shader::kSkyIrradianceTerms; ++k) {
    shader::SkyIrradiance unit{};
    unit.c[k] = glm::vec4(1.0f);
    t[k] = double(shader::skyIrradianceSum(unit, n).x);
  }
  return t;
}

// Solves a x = b in place for the symmetric positive definite a of the
// normal equations, three right-hand sides (rgb), by Gaussian elimination
// with partial pivoting.
template <size_t N>
void solve(std::array<std::array<double, N>, N>& a, std::array<glm::dvec3, N>& b) {
  for (size_t col = 0; col < N; ++col) {
    size_t pivot = col;
    for (size_t r = col + 1; r < N; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (size_t r = col + 1; r < N; ++r) {
      const double f = a[r][col] / a[col][col];
      for (size_t c = col; c < N; ++c) a[r][c] -= f * a[col][c];
      b[r] -= f * b[col];
    }
  }
  for (size_t col = N; col-- > 0;) {
    for (size_t c = col + 1; c < N; ++c) b[col] -= a[col][c] * b[c];
    b[col] /= a[col][col];
  }
}

}  // namespace

SkyBins::SkyBins(const SkyRadiance& sky, uint32_t bands, uint32_t azimuths, uint32_t subsamples) {
  const float solidAngle = glm::two_pi<float>() / float(bands * azimuths);
  const float perPoint = solidAngle / float(subsamples * subsamples);
  bins_.reserve(size_t(bands) * azimuths);
  for (uint32_t band = 0; band < bands; ++band) {
    for (uint32_t a = 0; a < azimuths; ++a) {
      glm::vec3 light(0.0f), weighted(0.0f), centre(0.0f);
      for (uint32_t k = 0; k < subsamples * subsamples; ++k) {
        const float up = (float(band) + (float(k / subsamples) + 0.5f) / float(subsamples)) / float(bands);
        const float phi =
            glm::two_pi<float>() * (float(a) + (float(k % subsamples) + 0.5f) / float(subsamples)) / float(azimuths);
        const float across = std::sqrt(std::max(0.0f, 1.0f - up * up));
        const glm::vec3 d(across * std::cos(phi), up, across * std::sin(phi));
        const glm::vec3 l = sky(d) * perPoint;
        light += l;
        weighted += (l.x + l.y + l.z) * d;
        centre += d;
      }
      // A dark bin's light comes from its middle.
      const glm::vec3 from = glm::length(weighted) > 0.0f ? weighted : centre;
      bins_.push_back({glm::normalize(from), light});
    }
  }
}

glm::vec3 SkyBins::irradianceUp() const {
  glm::vec3 e(0.0f);
  for (const Bin& bin : bins_) e += bin.light * bin.direction.y;
  return e;
}

shader::SkyIrradiance fitSkyIrradiance(const SkyBins& sky, glm::vec3 below) {
  constexpr size_t kTerms = shader::kSkyIrradianceTerms;
  std::array<std::array<double, kTerms>, kTerms> normal{};
  std::array<glm::dvec3, kTerms> rhs{};
  for (uint32_t i = 0; i < kFitNormals; ++i) {
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(kFitNormals);
    const float r = std::sqrt(std::max(0.0f, 1.0f - y * y)), a = 2.39996323f * float(i);  // the golden angle
    const glm::vec3 n(r * std::cos(a), y, r * std::sin(a));
    // The uniform radiance below lights n by the part of the lower
    // hemisphere it faces: pi L (1 - n.y) / 2.
    glm::dvec3 e = glm::dvec3(below) * (glm::pi<double>() * 0.5 * (1.0 - double(n.y)));
    for (const SkyBins::Bin& bin : sky.bins())
      e += glm::dvec3(bin.light) * double(std::max(glm::dot(n, bin.direction), 0.0f));
    const Terms t = termsAt(n);
    for (size_t j = 0; j < kTerms; ++j) {
      rhs[j] += t[j] * e;
      for (size_t k = 0; k < kTerms; ++k) normal[j][k] += t[j] * t[k];
    }
  }
  solve(normal, rhs);
  shader::SkyIrradiance s{};
  for (size_t k = 0; k < kTerms; ++k) s.c[k] = glm::vec4(glm::vec3(rhs[k]), 0.0f);
  return s;
}

}  // namespace tp::render
