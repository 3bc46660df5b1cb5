#include "render/env_sh.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "shared/env_sampling.h"

namespace tp::render {

namespace {

// Antiderivatives in theta of sin(theta) times the theta factors of the
// basis (s = sin, c = cos; the extra sin is d omega's): s, s c, s c^2, s^2,
// s^2 c, s^3.
struct ThetaTerms {
  double s, sc, scc, ss, ssc, sss;
};

ThetaTerms thetaAntiderivative(double t) {
  const double s = std::sin(t), c = std::cos(t);
  return {-c, 0.5 * s * s, -c * c * c / 3.0, 0.5 * t - 0.25 * std::sin(2.0 * t), s * s * s / 3.0, -c + c * c * c / 3.0};
}

ThetaTerms thetaIntegral(double t0, double t1) {
  const ThetaTerms a = thetaAntiderivative(t0), b = thetaAntiderivative(t1);
  return {b.s - a.s, b.sc - a.sc, b.scc - a.scc, b.ss - a.ss, b.ssc - a.ssc, b.sss - a.sss};
}

// Integrals in phi of 1, cos, sin, cos 2phi, sin 2phi over [p0, p1].
struct PhiTerms {
  double one, c, s, c2, s2;
};

PhiTerms phiIntegral(double p0, double p1) {
  return {p1 - p0, std::sin(p1) - std::sin(p0), std::cos(p0) - std::cos(p1),
          0.5 * (std::sin(2.0 * p1) - std::sin(2.0 * p0)), 0.5 * (std::cos(2.0 * p0) - std::cos(2.0 * p1))};
}

}  // namespace

shader::Sh9 projectSh9(const SkyImage& image, float maxTheta) {
  const uint32_t w = image.width, h = image.height;
  std::vector<PhiTerms> columns(w);
  for (uint32_t i = 0; i < w; ++i) {
    // phi = (u - 1/2) 2 pi, as shared/equirect.h.
    columns[i] =
        phiIntegral((double(i) / w - 0.5) * glm::two_pi<double>(), (double(i + 1) / w - 0.5) * glm::two_pi<double>());
  }
  glm::dvec3 c[9] = {};
  for (uint32_t j = 0; j < h; ++j) {
    const double t0 = glm::pi<double>() * j / h, t1 = std::min(glm::pi<double>() * (j + 1) / h, double(maxTheta));
    if (t1 <= t0) break;
    const ThetaTerms t = thetaIntegral(t0, t1);
    glm::dvec3 one(0.0), cs(0.0), sn(0.0), c2(0.0), s2(0.0);  // the row's radiance times each phi term
    for (uint32_t i = 0; i < w; ++i) {
      const glm::dvec3 l(glm::vec3(image.texels[size_t(j) * w + i]));
      one += l * columns[i].one;
      cs += l * columns[i].c;
      sn += l * columns[i].s;
      c2 += l * columns[i].c2;
      s2 += l * columns[i].s2;
    }
    // x = s cos phi, y = c, z = s sin phi (shared/equirect.h); the basis of shared/sh9.h.
    c[0] += double(shader::kSh0) * t.s * one;
    c[1] += double(shader::kSh1) * t.sc * one;
    c[2] += double(shader::kSh1) * t.ss * sn;
    c[3] += double(shader::kSh1) * t.ss * cs;
    c[4] += double(shader::kSh2) * t.ssc * cs;
    c[5] += double(shader::kSh2) * t.ssc * sn;
    c[6] += double(shader::kSh20) * (3.0 * t.scc - t.s) * one;
    c[7] += double(shader::kSh2) * t.sss * 0.5 * s2;  // cos phi sin phi = sin 2phi / 2
    c[8] += double(shader::kSh22) * t.sss * c2;       // cos^2 phi - sin^2 phi = cos 2phi
  }
  shader::Sh9 sh{};
  for (int k = 0; k < 9; ++k) sh.c[k] = glm::vec4(glm::vec3(c[k]), 0.0f);
  return sh;
}

namespace {

// Calls visit(direction, radiance / density) for each of the n directions.
template <typename Visit>
void forEachSample(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n, glm::vec2 rotation,
                   Visit visit) {
  for (uint32_t k = 0; k < n; ++k) {
    const glm::vec2 xi = shader::envHammersley(k, n, rotation);
    EnvSample s;
    if (kind == EnvSampling::Importance) {
      s = sampler.sample(xi);
    } else {
      const glm::vec3 d = shader::envUniformDirection(xi);
      s = {d, 1.0f / (4.0f * glm::pi<float>()), sampler.texelOf(d)};
    }
    // The texel the sample was drawn in: its radiance is the one the density follows.
    const glm::vec3 radiance(image.texels[size_t(s.texel.y) * image.width + s.texel.x]);
    visit(s.direction, glm::dvec3(radiance) / double(s.pdf));
  }
}

}  // namespace

shader::Sh9 estimateSh9(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n,
                        glm::vec2 rotation) {
  glm::dvec3 c[9] = {};
  forEachSample(image, sampler, kind, n, rotation, [&](glm::vec3 d, glm::dvec3 weight) {
    for (uint32_t i = 0; i < 9; ++i) c[i] += weight * double(shader::sh9Basis(i, d));
  });
  shader::Sh9 sh{};
  for (int i = 0; i < 9; ++i) sh.c[i] = glm::vec4(glm::vec3(c[i] / double(n)), 0.0f);
  return sh;
}

glm::vec3 estimateIrradiance(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n,
                             glm::vec2 rotation, glm::vec3 normal) {
  glm::dvec3 sum(0.0);
  forEachSample(image, sampler, kind, n, rotation,
                [&](glm::vec3 d, glm::dvec3 weight) { sum += weight * double(std::max(glm::dot(d, normal), 0.0f)); });
  return glm::vec3(sum / double(n));
}

std::vector<glm::vec3> spiralNormals(int n) {
  std::vector<glm::vec3> normals;
  for (int k = 0; k < n; ++k) {
    const float y = 1.0f - 2.0f * (k + 0.5f) / n, r = std::sqrt(1.0f - y * y);
    const float phi = 2.399963229728653f * k;  // the golden angle
    normals.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
  }
  return normals;
}

}  // namespace tp::render
