// The GPU environment sampler (render/env_prefilter: CDFs built in compute,
// SH9 estimated in compute) against its CPU reference (render/env_sampler,
// render/env_sh), on a dim sky with a bright disc whose texels half floats
// hold exactly, so that both read the same radiance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "env_skies.hpp"
#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "render/env_prefilter.hpp"
#include "render/env_sampler.hpp"
#include "render/env_sh.hpp"
#include "render/sky_image.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 256, kHeight = 128;

// Grey (the sampler's weights radiance / density are then the same in every
// texel, so a direction that the float CDFs move across a texel edge weighs
// the same): 1/16 everywhere, 2048 in the disc.
struct DiscSkyOnGpu {
  explicit DiscSkyOnGpu(const gpu::Context& ctx, uint32_t maxSamples)
      : image(discSky(kWidth, kHeight, 0.0625f, 2048.0f)),
        cpu(image),
        texture(render::uploadSkyImage(ctx, image)),
        sampler(ctx.device(),
                vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest, .minFilter = vk::Filter::eNearest}),
        prefilter(ctx, kWidth, kHeight, maxSamples) {
    gpu::submitAndWait(ctx, [&](const vk::raii::CommandBuffer& cmd) { prefilter.recordCdf(cmd, texture, *sampler); });
  }
  render::SkyImage image;
  render::EnvSampler cpu;
  gpu::Image texture;
  vk::raii::Sampler sampler;
  render::EnvPrefilter prefilter;
};

using IblGpuTest = GpuTest;

// Float running sums of n positive terms, normalised: within (n + 1) 2^-24 of
// the exact (double) CDF; the marginal's terms carry the row sums' error too,
// so (W + H + 2) 2^-24 bounds both.
TEST_F(IblGpuTest, CdfsMatchTheCpuSampler) {
  DiscSkyOnGpu sky(ctx(), 64);
  const render::EnvSampler& cpu = sky.cpu;
  const std::vector<float> conditional = sky.prefilter.conditional(), marginal = sky.prefilter.marginal();
  const double bound = (kWidth + kHeight + 2) * std::ldexp(1.0, -24);
  double worstConditional = 0.0, worstMarginal = 0.0;
  for (size_t k = 0; k < conditional.size(); ++k) {
    worstConditional = std::max(worstConditional, std::abs(conditional[k] - cpu.columnCdf()[k]));
  }
  for (uint32_t j = 0; j <= kHeight; ++j)
    worstMarginal = std::max(worstMarginal, std::abs(marginal[j] - cpu.rowCdf()[j]));
  const double integralError = std::abs(marginal[kHeight + 1] - cpu.luminanceIntegral()) / cpu.luminanceIntegral();
  std::printf("GPU CDFs against the CPU's: conditional %.2e, marginal %.2e, integral %.2e (bound %.2e)\n",
              worstConditional, worstMarginal, integralError, bound);
  EXPECT_LE(worstConditional, bound);
  EXPECT_LE(worstMarginal, bound);
  EXPECT_LE(integralError, bound);
}

// The same Hammersley points through the GPU's and the CPU's CDFs: the
// coefficients agree to float accumulation (within 1e-4 of the band-0 one).
TEST_F(IblGpuTest, ShEstimateMatchesTheCpuEstimate) {
  constexpr uint32_t kSamples = 4096;
  DiscSkyOnGpu sky(ctx(), kSamples);
  for (const bool uniform : {false, true}) {
    const glm::vec2 rotation(0.3f, 0.6f);
    gpu::submitAndWait(ctx(), [&](const vk::raii::CommandBuffer& cmd) {
      sky.prefilter.recordSh(cmd, sky.texture, *sky.sampler, kSamples, rotation, uniform);
    });
    const shader::Sh9 got = sky.prefilter.sh();
    const shader::Sh9 expected = render::estimateSh9(
        sky.image, sky.cpu, uniform ? render::EnvSampling::Uniform : render::EnvSampling::Importance, kSamples,
        rotation);
    double worst = 0.0;
    for (int i = 0; i < 9; ++i) {
      for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(got.c[i][c] - expected.c[i][c])));
    }
    worst /= expected.c[0].g;
    std::printf("%s: GPU SH9 against the CPU's, worst %.2e of the band-0 coefficient\n",
                uniform ? "uniform" : "importance", worst);
    EXPECT_LE(worst, 1e-4);
  }
}

}  // namespace
}  // namespace tp::test
