#include "bench/bench_ibl_glossy.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "reference/glossy_quadrature.hpp"
#include "render/glossy_prefilter.hpp"
#include "shared/env_sampling.h"
#include "shared/equirect.h"
#include "shared/glossy.h"

namespace tp::app {
namespace {

constexpr uint32_t kCheckedTexels = 256;  // per level, where the quadrature is computed

struct Strategy {
  const char* name;
  render::GlossySampling (*split)(uint32_t samples);
};

const Strategy kStrategies[] = {
    {"mis",
     [](uint32_t n) {
       return render::GlossySampling{n / 2, n - n / 2};
     }},
    {"environment",
     [](uint32_t n) {
       return render::GlossySampling{n, 0};
     }},
    {"lobe",
     [](uint32_t n) {
       return render::GlossySampling{0, n};
     }},
};

// A fixed spread of texels of a w x h level: the Hammersley points over it.
std::vector<glm::uvec2> checkedTexels(uint32_t w, uint32_t h) {
  std::vector<glm::uvec2> texels;
  const uint32_t n = std::min(kCheckedTexels, w * h);
  for (uint32_t k = 0; k < n; ++k) {
    const glm::vec2 p = shader::envHammersley(k, n, glm::vec2(0.0f));
    texels.push_back(glm::min(glm::uvec2(p * glm::vec2(w, h)), glm::uvec2(w - 1, h - 1)));
  }
  return texels;
}

}  // namespace

void benchGlossyPrefilter(const gpu::Context& ctx, const render::SkyImage& sky, const BenchIblOptions& o) {
  if (o.glossySamples.empty()) return;
  const gpu::Image texture = render::uploadSkyImage(ctx, sky, "bench glossy environment");
  const vk::raii::Sampler sampler(
      ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest, .minFilter = vk::Filter::eNearest});
  const uint32_t base = render::glossyBaseWidth(sky.width), levels = render::glossyLevelCount(base);
  // The exact answers once: per level, at its checked texels.
  const render::GlossyQuadrature quadrature(sky);
  std::vector<std::vector<glm::uvec2>> texels(levels);
  std::vector<std::vector<double>> exact(levels);
  for (uint32_t k = 0; k < levels; ++k) {
    const uint32_t w = base >> k, h = (base / 2) >> k;
    texels[k] = checkedTexels(w, h);
    for (const glm::uvec2 t : texels[k]) {
      const glm::vec3 r = shader::equirectToDirection((glm::vec2(t) + 0.5f) / glm::vec2(w, h));
      exact[k].push_back(quadrature.radiance(r, shader::glossyLevelExponent(base, k)).y);
    }
  }
  base::AtomicFile csvFile(o.glossyCsv);
  std::ofstream csv(csvFile.tempPath());
  csv << "sampling,samples,level,exponent,prefilter_ms,rms_error,worst_error,map_width,levels,sky_width,device\n";
  std::printf(
      "\nglossy prefilter: map %ux%u, %u levels, from the %ux%u sky; error of the luminance at %u texels per "
      "level (RMS relative to the level's mean | worst relative to its brightest)\n",
      base, base / 2, levels, sky.width, sky.height, kCheckedTexels);
  std::printf("%-12s %8s %10s", "sampling", "samples", "GPU ms");
  for (uint32_t k = 0; k < levels; ++k) std::printf("   level %u (e %6.1f)", k, shader::glossyLevelExponent(base, k));
  std::printf("\n");
  for (const Strategy& strategy : kStrategies) {
    for (const uint32_t n : o.glossySamples) {
      render::GlossyPrefilter prefilter(ctx, sky.width, sky.height, strategy.split(n));
      std::vector<double> times;
      std::vector<std::vector<glm::vec4>> map;
      for (uint32_t r = 0; r < std::max(1u, std::min(o.repeats, 3u)); ++r) {
        double ms = 0.0;
        map = prefilter.prefilterAndRead(texture, *sampler, &ms);
        times.push_back(ms);
      }
      const double ms = median(times);
      std::printf("%-12s %8u %10.2f", strategy.name, n, ms);
      for (uint32_t k = 0; k < levels; ++k) {
        const uint32_t w = base >> k;
        std::vector<double> got;
        for (const glm::uvec2 t : texels[k]) got.push_back(map[k][size_t(t.y) * w + t.x].y);
        const render::GlossyLevelError error = render::glossyLevelError(got, exact[k]);
        const double rms = error.rms, worstRelative = error.worst;
        std::printf("   %8.2e | %8.2e", rms, worstRelative);
        csv << strategy.name << "," << n << "," << k << ","
            << formatNumber("%.6g", shader::glossyLevelExponent(base, k)) << "," << formatNumber("%.6g", ms) << ","
            << formatNumber("%.6g", rms) << "," << formatNumber("%.6g", worstRelative) << "," << base << "," << levels
            << "," << sky.width << ",\"" << ctx.deviceName() << "\"\n";
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  commitBenchCsv(csvFile, csv, "plot_bench_ibl_glossy.py", o.glossyPlot);
}

}  // namespace tp::app
