#include "bench/bench_ssao.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "bench/bench_pass_times.hpp"
#include "cli/gpu_session.hpp"
#include "reference/gbuffer_world.hpp"
#include "reference/reference_ao.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"

namespace tp::app {
namespace {

struct Case {
  std::string name;  // a preset's name, or the settings spelled out
  scene::Ao ao;
  bool preset = false;
};

std::vector<Case> benchCases() {
  std::vector<Case> cases;
  for (const char* preset : {"fast", "balanced", "quality", "baseline"})
    cases.push_back({preset, scene::aoPreset(preset), true});
  for (const char* resolution : {"full", "half"}) {
    for (const char* blur : {"off", "box", "bilateral"}) {
      for (unsigned kernel : {4u, 8u, 16u, 32u, 64u}) {
        scene::Ao ao;
        ao.kernelSize = kernel;
        ao.blur = blur;
        ao.resolution = resolution;
        cases.push_back({"k" + std::to_string(kernel) + " " + blur + " " + resolution, ao, false});
      }
    }
  }
  return cases;
}

// Most of a frame is open ground with AO 1 in both, which dilutes the mean:
// the error is also taken over the pixels where AO matters, those where the
// reference is below this (a set that does not depend on the case).
constexpr double kOccluded = 0.95;

struct Measured {
  double aoMs = 0.0, frameMs = 0.0;
  double mae = 0.0, rmse = 0.0, worst = 0.0;
  double maeOccluded = 0.0;  // over the pixels where the reference AO is under kOccluded (the same set in every case)
  size_t occludedPixels = 0;
  bool pareto = false;
};

// The AO's error against the reference where the frame has a surface.
void measureError(const render::RenderedFrame& frame, const std::vector<float>& reference, Measured& m) {
  double sum = 0.0, squares = 0.0, occludedSum = 0.0;
  size_t pixels = 0;
  for (size_t k = 0; k < reference.size(); ++k) {
    if (frame.gbufferDepth[k] >= 1.0f) continue;  // no surface: both 1
    const double e = std::abs(double(frame.ao[k]) - reference[k]);
    sum += e;
    squares += e * e;
    m.worst = std::max(m.worst, e);
    ++pixels;
    if (reference[k] < kOccluded) {
      occludedSum += e;
      ++m.occludedPixels;
    }
  }
  m.maeOccluded = m.occludedPixels ? occludedSum / double(m.occludedPixels) : std::nan("");
  m.mae = pixels ? sum / double(pixels) : std::nan("");
  m.rmse = pixels ? std::sqrt(squares / double(pixels)) : std::nan("");
}

// Pareto front: no other case is both faster and more accurate.
void markParetoFront(std::vector<Measured>& results) {
  for (size_t c = 0; c < results.size(); ++c) {
    results[c].pareto = true;
    for (size_t d = 0; d < results.size(); ++d) {
      const bool better = results[d].aoMs <= results[c].aoMs && results[d].mae <= results[c].mae &&
                          (results[d].aoMs < results[c].aoMs || results[d].mae < results[c].mae);
      if (better) results[c].pareto = false;
    }
  }
}

}  // namespace

int runBenchSsao(const BenchSsaoOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  const Resolution r = parseResolution(o.resolution, "bench ssao");
  const scene::Scene base = loadScene(o.scene, scene::defaultScene());
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  const std::vector<Case> cases = benchCases();
  std::vector<Measured> results(cases.size());

  // The reference, once: every case draws the same G-buffer.
  std::vector<float> reference;
  double referenceSeconds = 0.0;
  render::ReferenceAoOptions referenceOptions;
  referenceOptions.radius = base.ao.radius;
  referenceOptions.exactSpheres = false;  // the G-buffer's points lie on the spheres' tessellation
  for (size_t c = 0; c < cases.size(); ++c) {
    scene::Scene s = base;
    s.ao = cases[c].ao;
    s.ao.radius = base.ao.radius;
    s.ao.enabled = true;
    render::Renderer renderer(ctx, s, r.width, r.height);
    render::RenderedFrame frame;
    const PassTimes t = medianPassTimes(renderer, {.frame = o.frame, .hdr = true, .ao = true}, o.repeats,
                                        {render::passes::isAo}, frame);
    if (reference.empty()) {
      std::fprintf(stderr, "bench ssao: reference AO at %ux%u, %u rays per pixel\n", r.width, r.height,
                   referenceOptions.rays);
      const render::WorldGbuffer g = render::worldGbuffer(frame);
      render::ReferenceAoOptions options = referenceOptions;
      options.originOffset = g.uncertainty;
      const auto start = std::chrono::steady_clock::now();
      reference = render::referenceAmbientOcclusion(s, nullptr, float(o.frame) * s.water.frameTime, g.position,
                                                    g.normal, r.width, r.height, options);
      referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    Measured& m = results[c];
    m.aoMs = t.groups[0];
    m.frameMs = t.frame;
    measureError(frame, reference, m);
    std::fprintf(stderr, "bench ssao: %zu/%zu %s\n", c + 1, cases.size(), cases[c].name.c_str());
  }
  markParetoFront(results);

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "case,preset,pattern,kernel,blur,resolution,depth_lookup,ao_ms,frame_ms,mae,rmse,max_error,mae_occluded,"
         "occluded_pixels,pareto,width,height,"
         "reference_rays,reference_s,device\n";
  std::printf("%-24s %9s %9s %8s %8s %8s %9s %6s\n", "case", "AO ms", "frame ms", "MAE", "RMSE", "worst", "MAE occl",
              "front");
  for (size_t c = 0; c < cases.size(); ++c) {
    const Case& k = cases[c];
    const Measured& m = results[c];
    std::printf("%-24s %9.3f %9.3f %8.4f %8.4f %8.4f %9.4f %6s\n", k.name.c_str(), m.aoMs, m.frameMs, m.mae, m.rmse,
                m.worst, m.maeOccluded, m.pareto ? "*" : "");
    csv << k.name << "," << (k.preset ? 1 : 0) << "," << k.ao.pattern << "," << k.ao.kernelSize << "," << k.ao.blur
        << "," << k.ao.resolution << "," << k.ao.depthLookup << "," << formatNumber("%.6g", m.aoMs) << ","
        << formatNumber("%.6g", m.frameMs) << "," << formatNumber("%.6g", m.mae) << "," << formatNumber("%.6g", m.rmse)
        << "," << formatNumber("%.6g", m.worst) << "," << formatNumber("%.6g", m.maeOccluded) << "," << m.occludedPixels
        << "," << (m.pareto ? 1 : 0) << "," << r.width << "," << r.height << "," << referenceOptions.rays << ","
        << formatNumber("%.4g", referenceSeconds) << ",\"" << ctx.deviceName() << "\"\n";
  }
  commitBenchCsv(csvFile, csv, "plot_bench_ssao.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
