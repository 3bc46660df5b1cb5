#include "sim/water_scene.hpp"

#include <cmath>

#include "gpu/submit.hpp"
#include "shared/objects.h"
#include "sim/water_timeline.hpp"

namespace tp::sim {

WaterParams waterParams(const scene::Water& w) {
  return WaterParams{.n = w.grid,
                     .extent = w.extent,
                     .waveSpeed = w.waveSpeed,
                     .damping = w.damping,
                     .boundary = parseBoundary(w.boundary),
                     .maxSlope = w.maxSlope,
                     .gridDamping = w.gridDamping,
                     .sphereForcing = parseSphereForcing(w.sphereForcing)};
}

std::vector<uint32_t> solidCellsOf(const scene::Scene& s) {
  const uint32_t n = s.water.grid;
  const double h = s.water.extent / n;
  std::vector<uint32_t> solid;
  for (const auto& box : s.boxes) {
    const glm::vec3 half = 0.5f * box.size;
    if (!(box.center.y - half.y < s.water.level && s.water.level < box.center.y + half.y)) continue;
    if (solid.empty()) solid.assign(solidWords(n), 0u);
    const float yaw = glm::radians(box.yawDegrees);
    const glm::vec3 centre = worldToGrid(s.water, box.center);
    for (uint32_t j = 0; j < n; ++j) {
      for (uint32_t i = 0; i < n; ++i) {
        const glm::vec3 local =
            shader::toBoxFrame(glm::vec3(float((i + 0.5) * h) - centre.x, 0.0f, float((j + 0.5) * h) - centre.z), yaw);
        if (std::abs(local.x) < half.x && std::abs(local.z) < half.z) markSolid(solid, size_t(j) * n + i);
      }
    }
  }
  return solid;
}

WaterParams waterParams(const scene::Scene& s) {
  WaterParams p = waterParams(s.water);
  p.spillHeight = double(s.ground.height) - double(s.water.level);
  p.solid = solidCellsOf(s);
  return p;
}

void recordWaterSteps(const vk::raii::CommandBuffer& cmd, GpuStepper& water, const scene::Scene& scene, double start,
                      uint64_t count) {
  const double dt = waterStep(scene.water);
  bool moving = false;
  for (const auto& sphere : scene.spheres) moving |= !sphere.path.empty();
  if (!moving) {
    water.recordSteps(cmd, count, dt);
    return;
  }
  for (uint64_t step = 0; step < count; ++step) {
    const float t0 = float(start + double(step) * dt), t1 = float(start + double(step + 1) * dt);
    for (const auto& sphere : scene.spheres) {
      if (sphere.path.empty()) continue;
      water.recordSphereMove(cmd, worldToGrid(scene.water, scene::sphereCenterAt(sphere, t0)),
                             worldToGrid(scene.water, scene::sphereCenterAt(sphere, t1)), sphere.radius,
                             scene.water.level, dt);
    }
    water.recordSteps(cmd, 1, dt);
  }
}

WaterState simulateWater(const gpu::Context& ctx, const scene::Scene& scene, uint32_t frame) {
  WaterState result;
  simulateWaterFrames(ctx, scene, frame, frame, [&](uint32_t, const WaterState& water) {
    result = water;
    return true;
  });
  return result;
}

void simulateWaterFrames(const gpu::Context& ctx, const scene::Scene& scene, uint32_t first, uint32_t last,
                         const std::function<bool(uint32_t frame, const WaterState& water)>& atFrame) {
  GpuStepper stepper(ctx, waterParams(scene), waterInitialState(scene.water), StepKernel::ActiveTiles);
  const WaterClock clock{.substeps = waterSubsteps(scene.water)};  // from the start
  uint64_t done = 0;
  for (uint32_t frame = first;; ++frame) {
    // Each drop is due in exactly one of these disjoint runs of steps.
    const uint64_t steps = clock.stepsAt(frame);
    const std::vector<size_t> due = dueDrops(scene.water, clock, done, steps, {});
    gpu::submitAndWait(
        ctx, [&](const vk::raii::CommandBuffer& cmd) { recordWaterRun(cmd, stepper, scene, clock, done, steps, due); },
        "water simulation");
    done = steps;
    if (!atFrame(frame, stepper.download()) || frame == last) break;
  }
}

glm::vec3 worldToGrid(const scene::Water& w, glm::vec3 p) {
  return {p.x + 0.5f * w.extent, p.y, p.z + 0.5f * w.extent};
}

scene::Water withDynamicsOf(scene::Water water, const scene::Water& from) {
  water.waveSpeed = from.waveSpeed;
  water.damping = from.damping;
  water.gridDamping = from.gridDamping;
  water.boundary = from.boundary;
  water.maxSlope = from.maxSlope;
  water.sphereForcing = from.sphereForcing;
  return water;
}

bool sameWaterMotion(const scene::Water& a, const scene::Water& b) {
  scene::Water shading = a;
  shading.ior = b.ior;
  shading.absorption = b.absorption;
  shading.scattering = b.scattering;
  shading.scatteringAnisotropy = b.scatteringAnisotropy;
  shading.scatteringShadowPieces = b.scatteringShadowPieces;
  return shading == b;
}

uint32_t waterSubsteps(const scene::Water& w) { return substepsFor(waterParams(w), w.frameTime); }

double waterStep(const scene::Water& w) { return double(w.frameTime) / waterSubsteps(w); }

WaterState waterInitialState(const scene::Water& w) {
  const WaterParams p = waterParams(w);
  WaterState s = flatState(w.grid);
  for (const scene::Drop& d : w.drops) {
    if (d.frame != 0) continue;  // a later drop comes on its frame (water_timeline.hpp)
    const glm::vec3 centre = worldToGrid(w, {d.x, 0.0f, d.z});
    addDrop(s, w.extent, centre.x, centre.z, d.radius, d.amplitude);
  }
  startAtRest(s, p, waterStep(w));
  return s;
}

}  // namespace tp::sim
