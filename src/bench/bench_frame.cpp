#include "bench/bench_frame.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <vector>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "cli/gpu_session.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"

namespace tp::app {
namespace {

struct Variant {
  std::string name;
  std::function<void(scene::Scene&)> change;
};

std::vector<Variant> variants() {
  return {
      {"everything on", [](scene::Scene&) {}},
      {"no water", [](scene::Scene& s) { s.water.enabled = false; }},
      {"calm water", [](scene::Scene& s) { s.water.drops.clear(); }},
      // One ripple in a corner: the simulation steps only the tiles it reaches.
      {"a small ripple",
       [](scene::Scene& s) { s.water.drops = {{.x = 1.2f, .z = 1.2f, .radius = 0.15f, .amplitude = 0.04f}}; }},
      {"AO off", [](scene::Scene& s) { s.ao.enabled = false; }},
      {"objects out of view",
       [](scene::Scene& s) {
         for (auto& sphere : s.spheres) sphere.center += glm::vec3(8.0f, 0.0f, 12.0f);  // behind the default camera
         for (auto& box : s.boxes) box.center += glm::vec3(8.0f, 0.0f, 12.0f);
       }},
      {"camera over the water",
       [](scene::Scene& s) {
         s.camera.position = {0.6f, 1.6f, 1.2f};
         s.camera.target = {0.0f, -0.3f, -0.5f};
       }},
  };
}

struct Measured {
  double gpuMs = 0.0, wallMs = 0.0;                                      // medians per frame
  double passes = 0.0, dispatches = 0.0, draws = 0.0, workgroups = 0.0;  // means per frame
};

Measured measure(const gpu::Context& ctx, const scene::Scene& s, const Resolution& r, uint32_t frames, bool skipping) {
  render::Renderer renderer(ctx, s, r.width, r.height, {.skipping = skipping});
  renderer.render({.frame = 0});  // pipelines warm, cached passes filled
  std::vector<double> gpu, wall;
  Measured m;
  for (uint32_t frame = 1; frame <= frames; ++frame) {
    const auto start = std::chrono::steady_clock::now();
    const render::RenderedFrame f = renderer.render({.frame = frame});
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    double ms = 0.0;
    for (const auto& pass : f.passes) ms += pass.milliseconds;
    gpu.push_back(ms);
    m.passes += double(f.passes.size()) / frames;
    m.dispatches += double(f.counts.dispatches) / frames;
    m.draws += double(f.counts.draws) / frames;
    m.workgroups += double(f.counts.workgroups) / frames;
  }
  m.gpuMs = median(gpu);
  m.wallMs = median(wall);
  return m;
}

}  // namespace

int runBenchFrame(const BenchFrameOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  const Resolution r = parseResolution(o.resolution, "bench frame");
  if (o.frames < 1) throw std::runtime_error("bench frame: --frames must be at least 1");
  const scene::Scene base = loadScene(o.scene, scene::defaultScene());
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  // lavapipe's timestamps miss its deferred rasterization, so the saving is
  // given in wall time too (submission to readback, the same work in both).
  csv << "variant,skipping,gpu_ms,wall_ms,passes,dispatches,draws,workgroups,saving_gpu,saving_wall,frames,width,"
         "height,device\n";
  std::printf("%-22s %5s %9s %9s %7s %10s %6s %11s %8s %8s\n", "variant", "skip", "GPU ms", "wall ms", "passes",
              "dispatches", "draws", "workgroups", "save GPU", "save wall");
  for (const Variant& v : variants()) {
    scene::Scene s = base;
    v.change(s);
    std::fprintf(stderr, "bench frame: %s\n", v.name.c_str());
    const Measured off = measure(ctx, s, r, o.frames, false), on = measure(ctx, s, r, o.frames, true);
    const double savingGpu = 1.0 - on.gpuMs / off.gpuMs, savingWall = 1.0 - on.wallMs / off.wallMs;
    for (const auto& [skipping, m] : {std::pair{false, off}, std::pair{true, on}}) {
      const std::string gpuText = skipping ? formatNumber("%.1f%%", 100.0 * savingGpu) : "";
      const std::string wallText = skipping ? formatNumber("%.1f%%", 100.0 * savingWall) : "";
      std::printf("%-22s %5s %9.3f %9.3f %7.1f %10.1f %6.1f %11.0f %8s %8s\n", v.name.c_str(), skipping ? "on" : "off",
                  m.gpuMs, m.wallMs, m.passes, m.dispatches, m.draws, m.workgroups, gpuText.c_str(), wallText.c_str());
      csv << "\"" << v.name << "\"," << (skipping ? 1 : 0) << "," << formatNumber("%.6g", m.gpuMs) << ","
          << formatNumber("%.6g", m.wallMs) << "," << formatNumber("%.4g", m.passes) << ","
          << formatNumber("%.6g", m.dispatches) << "," << formatNumber("%.6g", m.draws) << ","
          << formatNumber("%.8g", m.workgroups) << "," << (skipping ? formatNumber("%.4g", savingGpu) : "") << ","
          << (skipping ? formatNumber("%.4g", savingWall) : "") << "," << o.frames << "," << r.width << "," << r.height
          << ",\"" << ctx.deviceName() << "\"\n";
    }
  }
  commitBenchCsv(csvFile, csv, "plot_bench_frame.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
