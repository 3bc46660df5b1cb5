// The sky's clouds (shared/sky.h) against exact answers: the irradiance of a
// uniform sky under full cover in closed form, and the coverage's end points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <random>

#include "shading/sky_model.hpp"
#include "shared/sky.h"

namespace tp::test {
namespace {

// A sky of constant radiance c: no glow, zenith = horizon.
scene::Sky uniformSky() {
  scene::Sky sky;
  sky.zenith = sky.horizon = glm::vec3(0.4f, 0.5f, 0.7f);
  sky.glow = glm::vec3(0.0f);
  return sky;
}

// The sky's irradiance on an up-facing surface, by the midpoint rule in
// (theta, phi) over the upper hemisphere (128 x 256), from the shared sky
// radiance the sky pass evaluates; the sun disk is left out, as in the
// lighting.
glm::dvec3 irradianceUp(const scene::Sky& sky) {
  constexpr int kTheta = 128, kPhi = 256;
  const shader::SkyParams p = render::skyParams(sky);
  const double dTheta = glm::half_pi<double>() / kTheta, dPhi = glm::two_pi<double>() / kPhi;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * dTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      sum += glm::dvec3(shader::skyRadiance(p, d, 0.0f)) * std::cos(theta) * std::sin(theta) * dTheta * dPhi;
    }
  }
  return sum;
}

}  // namespace

// Under full cover (coverage 1 makes every density cloud) the radiance at
// sin of elevation mu is c + (k - c) w(mu), w = smoothstep(0, a, mu), k the
// clouds' colour, a = kCloudHorizonFade. On an up-facing surface
//   E = 2 pi int_0^1 L mu dmu = pi c + 2 pi (k - c) (0.35 a^2 + (1 - a^2) / 2),
// with int_0^1 (3x^2 - 2x^3) x dx = 3/4 - 2/5 = 0.35. The midpoint rule of
// irradianceUp (128 steps in theta) meets w's second derivative, ~6/a^2,
// over the fade band: an error of order 1e-4 of E, hence the 1e-3 below.
// (The renderer lights with a polynomial fit of the same radiance's
// irradiance, render::sceneLight, whose own accuracy
// tests/sky_irradiance_test.cpp checks.)
TEST(SkyClouds, OvercastIrradianceMatchesTheClosedForm) {
  scene::Sky sky = uniformSky();
  sky.clouds.coverage = 1.0f;
  sky.clouds.color = glm::vec3(1.3f, 1.2f, 0.9f);
  const glm::dvec3 c(sky.zenith), k(sky.clouds.color);
  const double a = shader::kCloudHorizonFade;
  const glm::dvec3 exact =
      glm::pi<double>() * c + glm::two_pi<double>() * (k - c) * (0.35 * a * a + (1.0 - a * a) / 2.0);
  const glm::dvec3 e = irradianceUp(sky);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(e[ch], exact[ch], 1e-3 * exact[ch]) << "channel " << ch;
    std::printf("overcast irradiance, channel %d: %.6f, closed form %.6f (relative %.1e)\n", ch, e[ch], exact[ch],
                std::abs(e[ch] - exact[ch]) / exact[ch]);
  }
}

// Coverage 0 hides nothing, coverage 1 everything (once clear of the horizon
// fade), and the covered share of the sky grows with the coverage.
TEST(SkyClouds, CoverageRunsFromClearToOvercast) {
  scene::Sky sky = uniformSky();
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  std::vector<glm::vec3> directions;
  while (directions.size() < 20000) {
    const glm::vec3 d(coordinate(rng), coordinate(rng), coordinate(rng));
    const float len = glm::length(d);
    if (len > 0.1f && len <= 1.0f && d.y / len > shader::kCloudHorizonFade) directions.push_back(d / len);
  }
  double previous = -1.0;
  for (const float coverage : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
    sky.clouds.coverage = coverage;
    const shader::SkyParams p = render::skyParams(sky);
    double share = 0.0;
    for (const glm::vec3& d : directions) share += shader::cloudAmount(p, d);
    share /= double(directions.size());
    if (coverage == 0.0f) {
      EXPECT_EQ(share, 0.0);
    }
    if (coverage == 1.0f) {
      EXPECT_EQ(share, 1.0);
    }
    EXPECT_GT(share, previous) << "coverage " << coverage;
    previous = share;
    std::printf("coverage %.2f: mean cloud amount %.4f\n", coverage, share);
  }
}

}  // namespace tp::test
