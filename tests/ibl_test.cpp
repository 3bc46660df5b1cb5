// Image-based lighting against independent answers: the SH9 projection of a
// constant environment (irradiance pi L for every normal), the importance
// sampler's histogram against its density (chi-square), and importance
// against uniform sampling of a sky with a small bright disc, whose exact
// irradiance is a closed-form sum over its texels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <random>
#include <vector>

#include "env_skies.hpp"
#include "render/env_sampler.hpp"
#include "render/env_sh.hpp"
#include "shared/env_sampling.h"
#include "shared/sh9.h"

namespace tp::test {
namespace {

using render::EnvSampler;
using render::EnvSampling;
using render::SkyImage;

SkyImage constantImage(uint32_t w, uint32_t h, glm::vec3 radiance) {
  return SkyImage{w, h, std::vector<glm::vec4>(size_t(w) * h, glm::vec4(radiance, 1.0f))};
}

// The upper tail of chi-square with k degrees of freedom (Wilson-Hilferty's
// normal approximation: against the incomplete gamma function's series, within
// 8e-4 of the exact tail at the p-values measured here, 5% of it at p = 1e-3,
// for k = 15 and 511).
double chiSquareTail(double chi2, double k) {
  const double z = (std::cbrt(chi2 / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

TEST(IblTest, ConstantEnvironmentGivesPiLForEveryNormal) {
  const glm::vec3 l(0.3f, 0.5f, 0.9f);
  const SkyImage image = constantImage(64, 32, l);
  const shader::Sh9 whole = render::projectSh9(image, glm::pi<float>());
  const shader::Sh9 upper = render::projectSh9(image, glm::half_pi<float>());
  for (const glm::vec3& n : render::spiralNormals(50)) {
    const glm::vec3 e = shader::sh9Irradiance(whole, n), eUpper = shader::sh9Irradiance(upper, n);
    for (int c = 0; c < 3; ++c) {
      // Exact in double, then float coefficients and a float sum of 9 terms.
      EXPECT_NEAR(e[c], glm::pi<float>() * l[c], 2e-6f * l[c]) << n.x << "," << n.y << "," << n.z;
      // The sky above the horizon only: pi L (1 + n.y) / 2, which SH9 holds exactly.
      EXPECT_NEAR(eUpper[c], glm::pi<float>() * l[c] * 0.5f * (1.0f + n.y), 2e-6f * l[c]);
    }
  }
}

// The sampler's density follows the luminance exactly, so for a constant
// environment every sample's weight L / pdf is the same, 4 pi L: the
// estimates of the integral have zero variance, whatever the sample set.
TEST(IblTest, ConstantEnvironmentIsSampledWithZeroVariance) {
  const glm::vec3 l(0.3f, 0.5f, 0.9f);
  const SkyImage image = constantImage(64, 32, l);
  const EnvSampler sampler(image);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const float first = sampler.sample({0.5f, 0.5f}).pdf;
  EXPECT_NEAR(first, 1.0f / (4.0f * glm::pi<float>()), 1e-6f / (4.0f * glm::pi<float>()));  // float solid angles
  for (int k = 0; k < 10000; ++k) EXPECT_EQ(sampler.sample({uniform(rng), uniform(rng)}).pdf, first);
  // The band-0 coefficient of every estimate is sqrt(4 pi) L, exactly.
  for (const glm::vec2 rotation : {glm::vec2(0.0f), glm::vec2(0.37f, 0.81f), glm::vec2(0.93f, 0.12f)}) {
    for (const uint32_t n : {1u, 7u, 256u}) {
      const shader::Sh9 sh = render::estimateSh9(image, sampler, EnvSampling::Importance, n, rotation);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh.c[0][c], std::sqrt(4.0f * glm::pi<float>()) * l[c], 1e-5f * l[c]);
    }
  }
}

// A dim environment with one bright texel: the directions drawn, binned into
// the texels that hold them, against the probabilities written out here
// (luminance times the texel's solid angle, normalised), and within the
// bright texel against uniformity in u and cos(theta).
TEST(IblTest, BrightTexelHistogramMatchesItsDensity) {
  constexpr uint32_t w = 32, h = 16, brightI = 20, brightJ = 5;
  constexpr float bright = 500.0f;
  SkyImage image = constantImage(w, h, glm::vec3(1.0f));  // luminance 1
  image.texels[brightJ * w + brightI] = glm::vec4(bright, bright, bright, 1.0f);
  const EnvSampler sampler(image);

  std::vector<double> p(w * h);
  double total = 0.0;
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      const double band = std::cos(glm::pi<double>() * j / h) - std::cos(glm::pi<double>() * (j + 1) / h);
      p[j * w + i] = (i == brightI && j == brightJ ? bright : 1.0) * band;
      total += p[j * w + i];
    }
  }
  constexpr int kSamples = 200000, kSub = 4;
  std::vector<int> counts(w * h, 0), inside(kSub * kSub, 0);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const double cTop = std::cos(glm::pi<double>() * brightJ / h),
               cBottom = std::cos(glm::pi<double>() * (brightJ + 1) / h);
  for (int k = 0; k < kSamples; ++k) {
    const glm::vec3 d = sampler.sample({uniform(rng), uniform(rng)}).direction;
    const glm::uvec2 t = render::equirectTexel(d, w, h);
    ++counts[t.y * w + t.x];
    if (t == glm::uvec2(brightI, brightJ)) {
      const double u = shader::directionToEquirect(d).x * w - brightI, c = (cTop - d.y) / (cTop - cBottom);
      ++inside[std::min(int(c * kSub), kSub - 1) * kSub + std::min(int(u * kSub), kSub - 1)];
    }
  }
  double chi2 = 0.0, minExpected = 1e30;
  for (uint32_t k = 0; k < w * h; ++k) {
    const double expected = kSamples * p[k] / total;
    minExpected = std::min(minExpected, expected);
    chi2 += (counts[k] - expected) * (counts[k] - expected) / expected;
  }
  const double dof = w * h - 1, tail = chiSquareTail(chi2, dof);
  ASSERT_GE(minExpected, 5.0);  // the chi-square approximation's rule of thumb
  std::printf("texels: chi2 %.1f, %g dof, p-value %.3f\n", chi2, dof, tail);
  EXPECT_GT(tail, 1e-3);

  const double inBright = counts[brightJ * w + brightI], perCell = inBright / (kSub * kSub);
  double chi2Inside = 0.0;
  for (int c : inside) chi2Inside += (c - perCell) * (c - perCell) / perCell;
  const double insideTail = chiSquareTail(chi2Inside, kSub * kSub - 1);
  std::printf("inside the bright texel: chi2 %.1f, %d dof, p-value %.3f\n", chi2Inside, kSub * kSub - 1, insideTail);
  EXPECT_GT(insideTail, 1e-3);
}

// The density per steradian is the density of (u, v) over 2 pi^2 sin(theta):
// within a texel of probability P, u is uniform over 1/W and cos(theta)
// uniform over the row, so p(u, v) = P W pi sin(theta) / (cos theta_j - cos theta_j+1).
TEST(IblTest, SolidAngleDensityIsTheUvDensityOverTwoPiSquaredSinTheta) {
  constexpr uint32_t w = 32, h = 16;
  SkyImage image = constantImage(w, h, glm::vec3(0.2f));
  image.texels[3 * w + 9] = glm::vec4(40.0f, 30.0f, 20.0f, 1.0f);
  const EnvSampler sampler(image);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  double total = 0.0;
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      total += shader::envLuminance(glm::vec3(image.texels[j * w + i])) * shader::envTexelSolidAngle(j, w, h);
    }
  }
  for (int k = 0; k < 1000; ++k) {
    const render::EnvSample s = sampler.sample({uniform(rng), uniform(rng)});
    const uint32_t i = s.texel.x, j = s.texel.y;
    const double probability =
        shader::envLuminance(glm::vec3(image.texels[j * w + i])) * shader::envTexelSolidAngle(j, w, h) / total;
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - double(s.direction.y) * s.direction.y));
    const double band = std::cos(glm::pi<double>() * j / h) - std::cos(glm::pi<double>() * (j + 1) / h);
    const double pUv = probability * w * glm::pi<double>() * sinTheta / band;
    EXPECT_NEAR(shader::envSolidAnglePdf(float(pUv), float(sinTheta)), s.pdf, 1e-4f * s.pdf);
  }
}

// A dim sky (luminance 0.05) with a bright disc (luminance 2000: a sun), 256 x 128 texels.
SkyImage discSky() { return test::discSky(256, 128, 0.05f, 2000.0f); }

// The exact irradiance of the piecewise-constant image on an up-facing
// surface: each texel above the horizon gives L (2 pi / W) (sin^2 theta1 - sin^2 theta0) / 2.
double exactIrradianceUp(const SkyImage& image) {
  double e = 0.0;
  for (uint32_t j = 0; j < image.height / 2; ++j) {
    const double s0 = std::sin(glm::pi<double>() * j / image.height),
                 s1 = std::sin(glm::pi<double>() * (j + 1) / image.height);
    const double band = glm::two_pi<double>() / image.width * 0.5 * (s1 * s1 - s0 * s0);
    for (uint32_t i = 0; i < image.width; ++i) e += image.texels[j * image.width + i].g * band;
  }
  return e;
}

// Root-mean-square relative error of the irradiance estimate over 32 fixed
// Cranley-Patterson rotations of the n-point Hammersley set.
double rmsError(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n, double exact) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  double sum = 0.0;
  constexpr int kSets = 32;
  for (int k = 0; k < kSets; ++k) {
    const glm::vec2 rotation(uniform(rng), uniform(rng));
    const double e = render::estimateIrradiance(image, sampler, kind, n, rotation, {0.0f, 1.0f, 0.0f}).g;
    sum += (e - exact) * (e - exact);
  }
  return std::sqrt(sum / kSets) / exact;
}

// The fewest samples (a power of 2 up to 2^20) whose RMS error is within 1%.
uint32_t samplesForOnePercent(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, double exact) {
  for (uint32_t n = 4; n <= (1u << 20); n *= 2) {
    if (rmsError(image, sampler, kind, n, exact) <= 0.01) return n;
  }
  return 0;
}

TEST(IblTest, ImportanceSamplingNeedsFarFewerSamplesThanUniform) {
  const SkyImage image = discSky();
  const EnvSampler sampler(image);
  const double exact = exactIrradianceUp(image);
  const uint32_t importance = samplesForOnePercent(image, sampler, EnvSampling::Importance, exact);
  const uint32_t uniform = samplesForOnePercent(image, sampler, EnvSampling::Uniform, exact);
  std::printf("1%% RMS error of the irradiance: %u importance samples, %u uniform (%.0fx)\n", importance, uniform,
              double(uniform) / importance);
  ASSERT_GT(importance, 0u);
  ASSERT_GT(uniform, 0u);
  EXPECT_GE(uniform / importance, 1024u);  // measured: 64 against 262144 (4096x)
}

// The SH9 coefficients estimated by importance sampling converge to the
// exact texel-by-texel projection.
TEST(IblTest, ImportanceSampledSh9ConvergesToTheExactProjection) {
  const SkyImage image = discSky();
  const EnvSampler sampler(image);
  const shader::Sh9 exact = render::projectSh9(image, glm::pi<float>());
  double previous = 1e30;
  for (const uint32_t n : {64u, 1024u, 16384u}) {
    const shader::Sh9 estimate = render::estimateSh9(image, sampler, EnvSampling::Importance, n, {0.3f, 0.6f});
    double worst = 0.0, peak = 0.0;
    for (const glm::vec3& normal : render::spiralNormals(50)) {
      const float e = shader::sh9Irradiance(exact, normal).g;
      worst = std::max(worst, double(std::abs(shader::sh9Irradiance(estimate, normal).g - e)));
      peak = std::max(peak, double(e));
    }
    worst /= peak;  // relative to the brightest normal's: facing away from the disc the irradiance is near 0
    std::printf("SH9 irradiance from %u importance samples: worst error %.2e of the peak\n", n, worst);
    EXPECT_LT(worst, previous);
    previous = worst;
  }
  EXPECT_LT(previous, 1e-3);
}

}  // namespace
}  // namespace tp::test
