// The glossy lobe's arithmetic (shared/glossy.h) and the CPU quadrature of
// it over an environment (render/glossy_quadrature), against exact answers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "env_skies.hpp"
#include "reference/glossy_quadrature.hpp"
#include "render/env_sh.hpp"
#include "render/glossy_prefilter.hpp"
#include "shared/env_sampling.h"
#include "shared/glossy.h"

namespace tp::test {
namespace {

// A constant environment: the quadrature of a normalised lobe gives L back.
// Its cells are equal in u and cos(theta), so the error is the midpoint
// rule's on the lobe (measured, worst over 20 directions: 8.8e-4 relative at
// 64x32 texels and e = 6.5, 3.1e-4 at 128x64; the bound is 1e-3).
TEST(GlossyQuadrature, ConstantEnvironmentGivesItself) {
  for (const uint32_t w : {64u, 128u}) {
    const render::SkyImage sky{w, w / 2,
                               std::vector<glm::vec4>(size_t(w) * w / 2, glm::vec4(0.75f, 0.75f, 0.75f, 1.0f))};
    const render::GlossyQuadrature quadrature(sky);
    for (const float e : {1.0f, 1.6f, 6.5f, 26.0f, 104.0f, 415.0f}) {
      double worst = 0.0;
      for (const glm::vec3& r : render::spiralNormals(20)) {
        worst = std::max(worst, std::abs(quadrature.radiance(r, e).x / 0.75 - 1.0));
      }
      std::printf("glossy quadrature of a constant %ux%u environment, e = %5.1f: worst relative error %.2e\n", w, w / 2,
                  e, worst);
      EXPECT_LT(worst, 1e-3);
    }
  }
}

// The lod of each level's exponent is the level; the chain ends at 16 texels.
TEST(GlossyLevels, LodOfALevelsExponentIsThatLevel) {
  EXPECT_EQ(render::glossyBaseWidth(2048), 512u);
  EXPECT_EQ(render::glossyBaseWidth(300), 256u);
  EXPECT_EQ(render::glossyBaseWidth(16), 16u);
  EXPECT_EQ(render::glossyLevelCount(512), 6u);
  EXPECT_EQ(render::glossyLevelCount(16), 1u);
  for (const uint32_t base : {16u, 128u, 512u}) {
    for (uint32_t k = 0; k < render::glossyLevelCount(base); ++k) {
      EXPECT_NEAR(shader::glossyLod(shader::glossyLevelExponent(base, k), base), float(k), 1e-5f);
    }
  }
  EXPECT_FLOAT_EQ(shader::glossyExponent(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(shader::glossyExponent(0.5f), 31.0f);
}

// Lobe directions: their density is the lobe itself, so the mean of cos^k
// over them is (e + 1) / (e + k + 1) exactly.
TEST(GlossyLobe, SampledDirectionsFollowTheLobe) {
  const glm::vec3 r = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
  for (const float e : {1.0f, 30.0f, 400.0f}) {
    constexpr uint32_t n = 4096;
    double mean = 0.0;
    for (uint32_t k = 0; k < n; ++k) {
      const glm::vec2 xi = shader::envHammersley(k, n, glm::vec2(0.0f));
      mean += glm::dot(shader::glossyLobeDirection(r, e, xi), r) / n;
    }
    EXPECT_NEAR(mean, (e + 1.0) / (e + 2.0), 2e-4) << e;
  }
}

}  // namespace
}  // namespace tp::test
