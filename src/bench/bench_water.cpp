#include "bench/bench_water.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "bench/bench_output.hpp"
#include "bench/bench_pass_times.hpp"
#include "cli/gpu_session.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_scene.hpp"
#include "reference/reference_tracer.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/object_cast.h"
#include "shared/pool_trace.h"
#include "shared/shading.h"

namespace tp::app {
namespace {

struct View {
  std::string name;
  std::optional<scene::Camera> camera;  // none: the scene's own
};

// The scene's camera, one looking almost straight down (apparent depth's best
// case) and one at a grazing angle (its worst).
std::vector<View> benchViews(const scene::Scene& s) {
  scene::Camera overhead = s.camera, grazing = s.camera;
  overhead.position = {0.3f, 4.5f, 0.8f};
  overhead.target = {0.0f, s.water.level, 0.0f};
  grazing.position = {3.8f, 0.6f, 2.6f};
  grazing.target = {0.0f, -0.4f, 0.0f};
  return {{"scene", std::nullopt}, {"overhead", overhead}, {"grazing", grazing}};
}

struct FloorErrors {
  double accuratePx = 0.0, apparentPx = 0.0;
};

// Where each mode reads what lies under the water, against where the exact
// refracted ray (the reference's BVH, from the raster's own surface point and
// normal) meets it, in pixels on screen, averaged over the water's pixels.
// Accurate: the shared casts (tracePool on the floor mesh, then castObjects) the shader runs.
// Apparent: the texel the shader reads (the shared apparentDepthTexel), whose
// centre shows that point.
FloorErrors floorErrors(const scene::Scene& s, const render::RenderedFrame& aov, const std::vector<uint8_t>& water,
                        const sim::WaterState& state, float time) {
  std::vector<scene::Mesh> below;
  for (auto& m : render::sceneMeshes(s, &state, time)) {
    if (m.name != "water" && m.name.rfind("sphere", 0) != 0) below.push_back(std::move(m));
  }
  const scene::Scene placed = scene::sceneAt(s, time);
  const render::ReferenceScene exact(below, placed.spheres);
  const shader::SceneObjects objects = render::sceneObjects(placed);
  const render::PoolModel poolModel = render::poolModel(s);
  const shader::PoolParams& pool = poolModel.params;
  const auto u = render::frameUniforms(s, aov.width, aov.height);
  double accurate = 0.0, apparent = 0.0;
  size_t count = 0;
  for (size_t k = 0; k < water.size(); ++k) {
    if (!water[k]) continue;
    const glm::vec3 p(aov.position[k * 4], aov.position[k * 4 + 1], aov.position[k * 4 + 2]);
    const glm::vec3 n = glm::normalize(glm::vec3(aov.normal[k * 4], aov.normal[k * 4 + 1], aov.normal[k * 4 + 2]));
    const glm::vec3 view = glm::normalize(p - glm::vec3(u.cameraPosition));
    const glm::vec3 t = glm::refract(view, n, 1.0f / s.water.ior);
    if (glm::dot(t, t) == 0.0f || t.y >= 0.0f) continue;
    const render::ReferenceHit truth = exact.intersect(p, t, 0.0f);
    if (!truth.hit()) continue;
    const glm::vec2 truePixel = shader::screenPixel(u, p + truth.distance * t);

    const shader::PoolHit cast = shader::tracePool(pool, p, t, poolModel.floorVertices.data());
    const shader::ObjectHit object = shader::castObjects(objects, glm::uvec2(objects.count.z, objects.count.w), p, t,
                                                         cast.distance, shader::kSkipNoSphere);
    const float distance = object.distance > 0.0f ? object.distance : cast.distance;
    accurate += glm::length(shader::screenPixel(u, p + distance * t) - truePixel);

    apparent += glm::length(shader::apparentDepthTexel(pool, u, p, t) + 0.5f - truePixel);
    ++count;
  }
  if (count == 0) return {std::nan(""), std::nan("")};
  return {accurate / double(count), apparent / double(count)};
}

}  // namespace

int runBenchWater(const BenchWaterOptions& o) {
  checkBenchOutputs(o.csv, o.plot);
  std::vector<Resolution> resolutions;
  for (const auto& r : o.resolutions) resolutions.push_back(parseResolution(r, "bench water"));
  scene::Scene base = loadScene(o.scene, scene::defaultScene());
  base.render.caustics = false;  // the refraction modes alone: the caustics are measured on their own
  if (!base.water.enabled) throw std::runtime_error("bench water: the scene has no water");

  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  const sim::WaterState state = sim::simulateWater(ctx, base, o.frame);
  const float time = float(o.frame) * base.water.frameTime;

  base::AtomicFile csvFile(o.csv);
  std::ofstream csv(csvFile.tempPath());
  csv << "view,width,height,mode,refraction_ms,water_ms,underwater_ms,frame_ms,rmse,rmse_water,max_error_water,"
         "floor_error_px,water_pixels,reference_samples,reference_s,device\n";
  std::printf("%-9s %9s  %-9s %9s %9s %8s %10s %9s %10s\n", "view", "size", "mode", "refr ms", "frame ms", "RMSE",
              "RMSE water", "max water", "floor px");
  for (const View& view : benchViews(base)) {
    scene::Scene s = base;
    if (view.camera) s.camera = *view.camera;
    for (const Resolution& r : resolutions) {
      std::fprintf(stderr, "bench water: %s %ux%u: reference with %u samples\n", view.name.c_str(), r.width, r.height,
                   o.samples);
      const auto start = std::chrono::steady_clock::now();
      const render::RenderedFrame reference =
          render::renderReference(s, &state, o.frame, r.width, r.height, {.samples = o.samples});
      const double referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      render::Renderer aovRenderer(ctx, s, r.width, r.height, {.aovs = true});
      const render::RenderedFrame aov = aovRenderer.render({.frame = o.frame, .hdr = false, .aovs = true});
      const std::vector<uint8_t> water = render::waterPixelMask(aov, s.water);
      const FloorErrors floor = floorErrors(s, aov, water, state, time);

      for (const char* mode : {"accurate", "apparent"}) {
        s.render.refraction = mode;
        render::Renderer renderer(ctx, s, r.width, r.height);
        render::RenderedFrame frame;
        const PassTimes t =
            medianPassTimes(renderer, {.frame = o.frame, .hdr = true}, o.repeats,
                            {[](const render::PassKind* p) { return render::passes::isWater(p); },
                             [](const render::PassKind* p) { return p == &render::passes::kUnderwater; }},
                            frame);
        const double waterMs = t.groups[0], underwaterMs = t.groups[1];
        const auto all = render::tonemappedError(frame.rgba, reference.rgba, s.render.exposure);
        const auto onWater = render::tonemappedError(frame.rgba, reference.rgba, s.render.exposure, water);
        const double floorPx = std::string(mode) == "accurate" ? floor.accuratePx : floor.apparentPx;
        const double refractionMs = waterMs + underwaterMs;
        std::printf("%-9s %4ux%-4u  %-9s %9.3f %9.3f %8.4f %10.4f %9.4f %10.3f\n", view.name.c_str(), r.width, r.height,
                    mode, refractionMs, t.frame, all.rmse, onWater.rmse, onWater.maxError, floorPx);
        csv << view.name << "," << r.width << "," << r.height << "," << mode << ","
            << formatNumber("%.6g", refractionMs) << "," << formatNumber("%.6g", waterMs) << ","
            << formatNumber("%.6g", underwaterMs) << "," << formatNumber("%.6g", t.frame) << ","
            << formatNumber("%.6g", all.rmse) << "," << formatNumber("%.6g", onWater.rmse) << ","
            << formatNumber("%.6g", onWater.maxError) << "," << formatNumber("%.6g", floorPx) << "," << onWater.pixels
            << "," << o.samples << "," << formatNumber("%.4g", referenceSeconds) << ",\"" << ctx.deviceName() << "\"\n";
      }
    }
  }
  commitBenchCsv(csvFile, csv, "plot_bench_water.py", o.plot);
  return session.finish();
}

}  // namespace tp::app
