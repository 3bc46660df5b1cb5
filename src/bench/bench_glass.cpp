#include "bench/bench_glass.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "bench/bench_pass_times.hpp"
#include "cli/gpu_session.hpp"
#include "reference/glass_view.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_tracer.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"

namespace tp::app {
namespace {

// The raster's error is taken at 4x4 samples per pixel, box filtered, to meet
// the reference's samples at the silhouette (tests/glass_test.cpp does the same).
constexpr uint32_t kSupersample = 4;

struct Measured {
  double backMs = 0.0, frontMs = 0.0, frameMs = 0.0;
  double rmse = 0.0, maxError = 0.0;
  size_t pixels = 0;
};

}  // namespace

int runBenchGlass(const BenchGlassOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  const Resolution r = parseResolution(o.resolution, "bench glass");
  const scene::Scene base = loadScene(o.scene, render::glassSphereView());
  const uint32_t frame = 0;
  const scene::Scene placed = scene::sceneAt(base, 0.0f);
  if (!scene::hasGlassSpheres(placed)) {
    throw std::runtime_error("bench glass: the scene has no glass sphere");
  }
  for (uint32_t steps : o.steps) {
    scene::Scene s = base;
    s.render.glassSearchSteps = steps;
    scene::validateScene(s);  // the steps' bounds, before anything is measured
  }
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  std::fprintf(stderr, "bench glass: reference at %ux%u, %u samples per pixel\n", r.width, r.height, o.samples);
  const auto reference = render::renderReference(base, nullptr, frame, r.width, r.height, {.samples = o.samples});
  const auto mask = render::glassPixelMask(reference, placed);

  std::vector<Measured> results;
  for (uint32_t steps : o.steps) {
    scene::Scene s = base;
    s.render.glassSearchSteps = steps;
    Measured m;
    render::Renderer timed(ctx, s, r.width, r.height);
    render::RenderedFrame last;
    const PassTimes t =
        medianPassTimes(timed, {.frame = frame, .hdr = true}, o.repeats,
                        {[](const render::PassKind* p) { return p == &render::passes::kGlassBackFaces; },
                         [](const render::PassKind* p) { return p == &render::passes::kGlass; }},
                        last);
    m.backMs = t.groups[0];
    m.frontMs = t.groups[1];
    m.frameMs = t.frame;
    render::Renderer fine(ctx, s, r.width * kSupersample, r.height * kSupersample);
    const auto raster = fine.render({.frame = frame, .hdr = true});
    const auto filtered = render::boxDownsample(raster.rgba, raster.width, raster.height, kSupersample);
    const auto e = render::tonemappedError(filtered, reference.rgba, s.render.exposure, mask);
    m.rmse = e.rmse;
    m.maxError = e.maxError;
    m.pixels = e.pixels;
    results.push_back(m);
    std::fprintf(stderr, "bench glass: %u steps done\n", steps);
  }

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "steps,glass_ms,back_ms,front_ms,frame_ms,rmse,max_error,glass_pixels,width,height,supersample,"
         "reference_samples,device\n";
  std::printf("%6s %9s %9s %9s %9s %8s %8s %7s\n", "steps", "glass ms", "back ms", "front ms", "frame ms", "RMSE",
              "max", "pixels");
  for (size_t c = 0; c < results.size(); ++c) {
    const Measured& m = results[c];
    std::printf("%6u %9.3f %9.3f %9.3f %9.3f %8.4f %8.4f %7zu\n", o.steps[c], m.backMs + m.frontMs, m.backMs, m.frontMs,
                m.frameMs, m.rmse, m.maxError, m.pixels);
    csv << o.steps[c] << "," << formatNumber("%.6g", m.backMs + m.frontMs) << "," << formatNumber("%.6g", m.backMs)
        << "," << formatNumber("%.6g", m.frontMs) << "," << formatNumber("%.6g", m.frameMs) << ","
        << formatNumber("%.6g", m.rmse) << "," << formatNumber("%.6g", m.maxError) << "," << m.pixels << "," << r.width
        << "," << r.height << "," << kSupersample << "," << o.samples << ",\"" << ctx.deviceName() << "\"\n";
  }
  commitBenchCsv(csvFile, csv, "plot_bench_glass.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
