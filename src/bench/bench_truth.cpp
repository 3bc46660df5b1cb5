#include "bench/bench_truth.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "cli/frame_samples.hpp"
#include "cli/gpu_session.hpp"
#include "cli/scene_options.hpp"
#include "reference/image_error.hpp"
#include "reference/path_tracer.hpp"
#include "render/renderer.hpp"
#include "sim/water_scene.hpp"

namespace tp::app {
namespace {

// The regions a frame's error is told apart over, by the truth's first
// surface at each pixel's centre.
enum Region : uint8_t { kSky, kPool, kObjects, kGround, kRegions };
constexpr const char* kRegionNames[kRegions] = {"sky", "pool", "objects", "ground"};

// Within this of a sphere's surface or a box's, in metres, a point is the object's.
constexpr float kOnObject = 2e-3f;

Region regionOf(const scene::Scene& placed, glm::vec3 p) {
  if (!std::isfinite(p.x)) return kSky;
  for (const scene::Sphere& s : placed.spheres)
    if (std::abs(glm::distance(p, s.center) - s.radius) < kOnObject) return kObjects;
  for (const scene::Box& b : placed.boxes) {
    // Within the box's bounding sphere: boxes are few and small beside the pool.
    if (glm::distance(p, b.center) <= 0.5f * glm::length(b.size) + kOnObject) return kObjects;
  }
  const float half = 0.5f * placed.water.extent;
  if (placed.water.enabled && std::abs(p.x) <= half + kOnObject && std::abs(p.z) <= half + kOnObject &&
      p.y < placed.ground.height - kOnObject)
    return kPool;
  return kGround;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

struct Measured {
  std::string scene;
  double rasterSeconds = 0.0, truthSeconds = 0.0;  // the truth's: one of its two seeds
  double truthNoise = 0.0;                         // tonemapped RMSE of the truth's mean from its limit, estimated
  render::ImageError frame;
  render::ImageError regions[kRegions];
};

}  // namespace

int runBenchTruth(const BenchTruthOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  const Resolution r = parseResolution(o.resolution, "bench truth");
  std::vector<scene::Scene> scenes;
  for (const std::string& name : o.scenes)
    scenes.push_back(loadScene(SceneSource{name == "default" ? "" : name, {}}, scene::defaultScene()));
  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  std::vector<Measured> results;
  for (size_t i = 0; i < scenes.size(); ++i) {
    scene::Scene s = scenes[i];
    s.camera = scene::cameraAtFrame(s, o.frame);
    Measured m;
    m.scene = o.scenes[i];
    auto start = std::chrono::steady_clock::now();
    render::Renderer renderer(ctx, s, r.width, r.height);
    const render::RenderedFrame raster = renderSamples(renderer, {.frame = o.frame, .hdr = true}, o.rasterSamples);
    m.rasterSeconds = seconds(start);
    std::optional<sim::WaterState> water;
    if (s.water.enabled) water = sim::simulateWater(ctx, s, o.frame);
    std::fprintf(stderr, "bench truth: %s: path tracing %ux%u at %u samples\n", m.scene.c_str(), r.width, r.height,
                 o.samples);
    start = std::chrono::steady_clock::now();
    render::PathTracedFrame truth =
        render::renderPathTraced(s, water ? &*water : nullptr, o.frame, r.width, r.height, {.samples = o.samples});
    m.truthSeconds = seconds(start);
    // A second seed: the truth is the two renders' mean, and its own noise
    // the RMSE between them over 2 (each has sqrt 2 of the mean's).
    const render::PathTracedFrame second = render::renderPathTraced(s, water ? &*water : nullptr, o.frame, r.width,
                                                                    r.height, {.samples = o.samples, .seed = 1});
    m.truthNoise = render::tonemappedError(truth.frame.rgba, second.frame.rgba, s.render.exposure).rmse / 2.0;
    for (size_t k = 0; k < truth.frame.rgba.size(); ++k)
      truth.frame.rgba[k] = 0.5f * (truth.frame.rgba[k] + second.frame.rgba[k]);
    m.frame = render::tonemappedError(raster.rgba, truth.frame.rgba, s.render.exposure);
    const scene::Scene placed = scene::sceneAt(s, float(o.frame) * s.water.frameTime);
    std::vector<uint8_t> region(size_t(r.width) * r.height);
    for (size_t k = 0; k < region.size(); ++k) {
      const float* p = &truth.frame.position[k * 4];
      region[k] = regionOf(placed, glm::vec3(p[0], p[1], p[2]));
    }
    for (int g = 0; g < kRegions; ++g) {
      std::vector<uint8_t> mask(region.size());
      for (size_t k = 0; k < mask.size(); ++k) mask[k] = region[k] == g;
      m.regions[g] = render::tonemappedError(raster.rgba, truth.frame.rgba, s.render.exposure, mask);
    }
    results.push_back(m);
  }

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "scene,raster_s,truth_s,truth_noise,rmse,max_error";
  for (const char* name : kRegionNames) csv << ",rmse_" << name << ",pixels_" << name;
  csv << ",width,height,frame,truth_samples,raster_samples,device\n";
  std::printf("%-24s %9s %9s %8s %8s %8s %8s %8s %8s\n", "scene", "raster s", "truth s", "noise", "RMSE", "pool",
              "objects", "ground", "sky");
  for (const Measured& m : results) {
    std::printf("%-24s %9.3f %9.2f %8.4f %8.4f %8.4f %8.4f %8.4f %8.4f\n", m.scene.c_str(), m.rasterSeconds,
                m.truthSeconds, m.truthNoise, m.frame.rmse, m.regions[kPool].rmse, m.regions[kObjects].rmse,
                m.regions[kGround].rmse, m.regions[kSky].rmse);
    csv << "\"" << m.scene << "\"," << formatNumber("%.6g", m.rasterSeconds) << ","
        << formatNumber("%.6g", m.truthSeconds) << "," << formatNumber("%.6g", m.truthNoise) << ","
        << formatNumber("%.6g", m.frame.rmse) << "," << formatNumber("%.6g", m.frame.maxError);
    for (const render::ImageError& e : m.regions) csv << "," << formatNumber("%.6g", e.rmse) << "," << e.pixels;
    csv << "," << r.width << "," << r.height << "," << o.frame << "," << o.samples << "," << o.rasterSamples << ",\""
        << ctx.deviceName() << "\"\n";
  }
  commitBenchCsv(csvFile, csv, "plot_bench_truth.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
