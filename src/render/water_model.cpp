#include "render/water_model.hpp"

namespace tp::render {

sim::WaterParams waterParams(const scene::Water& w) {
  return sim::WaterParams{.n = w.grid,
                          .extent = w.extent,
                          .waveSpeed = w.waveSpeed,
                          .damping = w.damping,
                          .boundary = sim::parseBoundary(w.boundary),
                          .maxSlope = w.maxSlope};
}

uint32_t waterSubsteps(const scene::Water& w) { return sim::substepsFor(waterParams(w), w.frameTime); }

double waterStep(const scene::Water& w) { return double(w.frameTime) / waterSubsteps(w); }

sim::WaterState waterInitialState(const scene::Water& w) {
  const sim::WaterParams p = waterParams(w);
  sim::WaterState s = sim::flatState(w.grid);
  const double half = 0.5 * w.extent;
  for (const scene::Drop& d : w.drops) sim::addDrop(s, w.extent, d.x + half, d.z + half, d.radius, d.amplitude);
  sim::startAtRest(s, p, waterStep(w));
  return s;
}

std::vector<uint32_t> waterGridIndices(uint32_t n) {
  std::vector<uint32_t> indices;
  indices.reserve(size_t(n - 1) * (n - 1) * 6);
  for (uint32_t j = 0; j + 1 < n; ++j) {
    for (uint32_t i = 0; i + 1 < n; ++i) {
      const uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      indices.insert(indices.end(), {a, c, b, b, c, d});
    }
  }
  return indices;
}

shader::WaterSurfaceParams waterSurfaceParams(const scene::Scene& scene) {
  const scene::Water& w = scene.water;
  const scene::Ground& g = scene.ground;
  return shader::WaterSurfaceParams{
      .placement = {-0.5f * w.extent, w.level, -0.5f * w.extent, w.extent / float(w.grid)},
      .absorption = glm::vec4(w.absorption, w.ior),
      .grid = {w.grid, 0u, 0u, 0u},
      .ground = {.plane = {g.halfExtent, g.height, g.checkerSize, 0.0f},
                 .albedoA = glm::vec4(g.albedoA, 0.0f),
                 .albedoB = glm::vec4(g.albedoB, 0.0f)},
  };
}

std::vector<scene::Mesh> sceneMeshes(const scene::Scene& scene, const sim::WaterState* water) {
  std::vector<scene::Mesh> meshes;
  const scene::Ground& g = scene.ground;
  const float e = g.halfExtent, y = g.height;
  meshes.push_back({"ground", {{-e, y, -e}, {e, y, -e}, {e, y, e}, {-e, y, e}}, {0, 3, 1, 1, 3, 2}});
  if (water) {
    const shader::WaterSurfaceParams p = waterSurfaceParams(scene);
    const auto cells = sim::toCells(*water, scene.water.extent);
    scene::Mesh surface{"water", {}, waterGridIndices(water->n)};
    surface.positions.reserve(cells.size());
    for (const auto& c : cells) surface.positions.push_back({p.placement.x + c.x, p.placement.y + c.u, p.placement.z + c.z});
    meshes.push_back(std::move(surface));
  }
  return meshes;
}

}  // namespace tp::render
