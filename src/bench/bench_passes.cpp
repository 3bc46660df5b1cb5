#include "bench/bench_passes.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "cli/gpu_session.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"

namespace tp::app {
namespace {

struct PassTimes {
  std::vector<double> wall, gpu;
};

struct Measured {
  double frameMs = 0.0;            // median wall time of a frame submitted whole
  std::vector<std::string> order;  // the passes, in the order first recorded
  std::map<std::string, PassTimes> passes;
};

// The scene's camera where its path or turntable puts it at `frame`, as
// render --frames moves it: a still camera's frame keeps what a moving
// camera's draws again (the SSAO).
render::RenderedFrame renderAt(render::Renderer& renderer, const scene::Scene& s, render::FrameRequest request) {
  if (scene::isAnimated(s.camera)) renderer.setCamera(scene::cameraAtFrame(s, request.frame));
  return renderer.render(request);
}

// The frame `render` writes (its HDR colour read back), or with `shown` the
// one the viewer shows (the tonemapped image left on the GPU).
render::FrameRequest requestFor(uint32_t frame, bool shown, bool passWallTimes) {
  return {.frame = frame, .hdr = !shown, .passWallTimes = passWallTimes, .present = shown};
}

Measured measure(const gpu::Context& ctx, const scene::Scene& s, const Resolution& r, uint32_t frames, bool shown) {
  render::Renderer renderer(ctx, s, r.width, r.height);
  renderAt(renderer, s, requestFor(0, shown, false));  // pipelines compiled, cached passes filled
  Measured m;
  std::vector<double> frameMs;
  uint32_t frame = 1;
  for (uint32_t k = 0; k < frames; ++k, ++frame) {
    const auto start = std::chrono::steady_clock::now();
    renderAt(renderer, s, requestFor(frame, shown, false));
    frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  m.frameMs = median(frameMs);
  for (uint32_t k = 0; k < frames; ++k, ++frame) {
    for (const auto& pass : renderAt(renderer, s, requestFor(frame, shown, true)).passes) {
      if (!m.passes.count(pass.name)) m.order.push_back(pass.name);
      m.passes[pass.name].wall.push_back(pass.wallMilliseconds);
      m.passes[pass.name].gpu.push_back(pass.milliseconds);
    }
  }
  return m;
}

}  // namespace

int runBenchPasses(const BenchPassesOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  std::vector<Resolution> resolutions;
  for (const auto& r : o.resolutions) resolutions.push_back(parseResolution(r, "bench passes"));
  if (o.frames < 1) throw std::runtime_error("bench passes: --frames must be at least 1");
  const scene::Scene s = loadScene(o.scene, scene::defaultScene());
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "width,height,pass,wall_ms,gpu_ms,runs,frame_wall_ms,fps,frames,device\n";
  std::printf("%-10s %-20s %9s %9s %5s\n", "size", "pass", "wall ms", "GPU ms", "runs");
  for (const Resolution& r : resolutions) {
    std::fprintf(stderr, "bench passes: %ux%u\n", r.width, r.height);
    const Measured m = measure(ctx, s, r, o.frames, o.shown);
    const std::string size = std::to_string(r.width) + "x" + std::to_string(r.height);
    const double fps = 1000.0 / m.frameMs;
    for (const std::string& name : m.order) {
      const PassTimes& t = m.passes.at(name);
      const double wall = median(t.wall), gpu = median(t.gpu);
      // A cached pass runs in some frames only: its runs say in how many.
      std::printf("%-10s %-20s %9.3f %9.3f %5zu\n", size.c_str(), name.c_str(), wall, gpu, t.wall.size());
      csv << r.width << "," << r.height << ",\"" << name << "\"," << formatNumber("%.6g", wall) << ","
          << formatNumber("%.6g", gpu) << "," << t.wall.size() << "," << formatNumber("%.6g", m.frameMs) << ","
          << formatNumber("%.4g", fps) << "," << o.frames << ",\"" << ctx.deviceName() << "\"\n";
    }
    std::printf("%-10s %-20s %9.3f %9s %5s  %.2f fps, the frame submitted whole\n", size.c_str(), "frame", m.frameMs,
                "", "", fps);
  }
  commitBenchCsv(csvFile, csv, "plot_bench_passes.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
