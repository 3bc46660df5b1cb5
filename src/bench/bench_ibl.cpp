#include "bench/bench_ibl.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/packing.hpp>
#include <stdexcept>
#include <string>

#include "base/atomic_file.hpp"
#include "bench/bench_ibl_glossy.hpp"
#include "bench/bench_output.hpp"
#include "cli/gpu_session.hpp"
#include "gpu/submit.hpp"
#include "gpu/timer.hpp"
#include "render/env_prefilter.hpp"
#include "render/env_sh.hpp"
#include "render/sky_image.hpp"
#include "scene/scene_file.hpp"
#include "shading/sky_model.hpp"
#include "shared/equirect.h"
#include "shared/sky.h"

namespace tp::app {
namespace {

// The worst irradiance error over the normals, relative to the brightest normal's irradiance.
double irradianceError(const shader::Sh9& estimate, const shader::Sh9& exact, const std::vector<glm::vec3>& normals) {
  double worst = 0.0, peak = 0.0;
  for (const glm::vec3& n : normals) {
    const glm::vec3 e = shader::sh9Irradiance(exact, n);
    worst = std::max(worst, double(glm::length(shader::sh9Irradiance(estimate, n) - e)));
    peak = std::max(peak, double(glm::length(e)));
  }
  return worst / peak;
}

struct Row {
  const char* sampling;
  uint32_t samples;
  double shMs, rmsError;
};

}  // namespace

int runBenchIbl(const BenchIblOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  if (!o.glossySamples.empty()) checkBenchOutputs(o.glossyCsv, o.glossyPlot);
  if (o.width < 16 || o.width > 8192 || o.width % 2) {
    throw std::runtime_error("bench ibl: --width " + std::to_string(o.width) + " is not even and 16 to 8192");
  }
  const scene::Scene s = loadScene(o.scene, scene::defaultScene());
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  const render::SkyImage image = render::proceduralSkyImage(s.sky, o.width);
  const auto start = std::chrono::steady_clock::now();
  const shader::Sh9 exact = render::projectSh9(image, glm::pi<float>());
  const double projectionMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const std::vector<glm::vec3> normals = render::spiralNormals(100);
  const gpu::Image texture = render::uploadSkyImage(ctx, image, "bench environment");
  const vk::raii::Sampler sampler(
      ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest, .minFilter = vk::Filter::eNearest});
  uint32_t maxSamples = 1;
  for (uint32_t n : o.samples) maxSamples = std::max(maxSamples, n);
  render::EnvPrefilter prefilter(ctx, image.width, image.height, maxSamples);
  gpu::GpuTimer timer(ctx, 1);
  auto timed = [&](const std::function<void(const vk::raii::CommandBuffer&)>& record) {
    gpu::submitAndWait(
        ctx,
        [&](const vk::raii::CommandBuffer& cmd) {
          timer.reset(cmd);
          const uint32_t scope = timer.begin(cmd, "ibl");
          record(cmd);
          timer.end(cmd, scope);
        },
        "bench ibl");
    return timer.read().front().milliseconds;
  };
  std::vector<double> cdfTimes;
  for (uint32_t r = 0; r < o.repeats; ++r) {
    cdfTimes.push_back(timed([&](const vk::raii::CommandBuffer& cmd) { prefilter.recordCdf(cmd, texture, *sampler); }));
  }
  const double cdfMs = median(cdfTimes);

  std::vector<Row> rows;
  for (const bool uniform : {false, true}) {
    for (const uint32_t n : o.samples) {
      std::vector<double> times;
      double squares = 0.0;
      for (uint32_t r = 0; r < o.rotations; ++r) {
        // Fixed rotations (the golden ratio's multiples modulo 1): deterministic, independent sets.
        const glm::vec2 rotation = glm::fract(glm::vec2(0.6180339887f, 0.7548776662f) * float(r + 1));
        times.push_back(timed([&](const vk::raii::CommandBuffer& cmd) {
          prefilter.recordSh(cmd, texture, *sampler, n, rotation, uniform);
        }));
        const double e = irradianceError(prefilter.sh(), exact, normals);
        squares += e * e;
      }
      rows.push_back({uniform ? "uniform" : "importance", n, median(times), std::sqrt(squares / o.rotations)});
      std::fprintf(stderr, "bench ibl: %s %u\n", rows.back().sampling, n);
    }
  }

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "sampling,samples,sh_ms,cdf_ms,rms_error,projection_cpu_ms,width,height,rotations,device\n";
  std::printf("environment %ux%u, CDF build %.3f ms (GPU), exact SH9 projection %.1f ms (CPU, one thread)\n",
              image.width, image.height, cdfMs, projectionMs);
  std::printf("%-11s %8s %9s %11s\n", "sampling", "samples", "SH ms", "RMS error");
  for (const Row& r : rows) {
    std::printf("%-11s %8u %9.3f %11.3e\n", r.sampling, r.samples, r.shMs, r.rmsError);
    csv << r.sampling << "," << r.samples << "," << formatNumber("%.6g", r.shMs) << "," << formatNumber("%.6g", cdfMs)
        << "," << formatNumber("%.6g", r.rmsError) << "," << formatNumber("%.4g", projectionMs) << "," << image.width
        << "," << image.height << "," << o.rotations << ",\"" << ctx.deviceName() << "\"\n";
  }
  commitBenchCsv(csvFile, csv, "plot_bench_ibl.py", o.plot);
  benchGlossyPrefilter(ctx, image, o);
  return session.finish();
}

}  // namespace tp::app
