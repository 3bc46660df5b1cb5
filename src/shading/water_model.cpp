#include "shading/water_model.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shared/water_scattering.h"

namespace tp::render {

std::vector<glm::vec3> waterVertexNormals(const sim::WaterState& water, float extent) {
  const int64_t n = water.n;
  const float h = extent / float(n);
  auto u = [&](int64_t i, int64_t j) {
    return water.u[size_t(std::clamp<int64_t>(j, 0, n - 1) * n + std::clamp<int64_t>(i, 0, n - 1))];
  };
  std::vector<glm::vec3> normals(size_t(n * n));
  for (int64_t j = 0; j < n; ++j) {
    for (int64_t i = 0; i < n; ++i) {
      const float dx = float(std::min(i + 1, n - 1) - std::max<int64_t>(i - 1, 0)) * h;
      const float dz = float(std::min(j + 1, n - 1) - std::max<int64_t>(j - 1, 0)) * h;
      const float dudx = float(u(i + 1, j) - u(i - 1, j)) / dx, dudz = float(u(i, j + 1) - u(i, j - 1)) / dz;
      normals[size_t(j * n + i)] = glm::normalize(glm::vec3(-dudx, 1.0f, -dudz));
    }
  }
  return normals;
}

namespace {

// The rows (and columns) a grid of n vertices a side keeps at `step`: every
// step-th from the first, and the last.
std::vector<uint32_t> gridLines(uint32_t n, uint32_t step) {
  if (step == 0) throw std::invalid_argument("a grid's step must be at least 1");
  std::vector<uint32_t> lines;
  for (uint32_t i = 0; i + 1 < n; i += step) lines.push_back(i);
  lines.push_back(n - 1);
  return lines;
}

}  // namespace

std::vector<uint32_t> waterGridStrips(uint32_t n, uint32_t step) {
  const std::vector<uint32_t> lines = gridLines(n, step);
  std::vector<uint32_t> indices;
  indices.reserve((lines.size() - 1) * (2 * lines.size() + 1));
  for (size_t r = 0; r + 1 < lines.size(); ++r) {
    // a0 c0 a1 c1 ...: strip triangle 2i is (a, c, b) and 2i+1 (b, c, d), as in the list.
    for (const uint32_t i : lines) indices.insert(indices.end(), {lines[r] * n + i, lines[r + 1] * n + i});
    indices.push_back(kStripRestart);
  }
  return indices;
}

std::vector<uint32_t> waterGridIndices(uint32_t n, uint32_t step) {
  const std::vector<uint32_t> lines = gridLines(n, step);
  std::vector<uint32_t> indices;
  indices.reserve((lines.size() - 1) * (lines.size() - 1) * 6);
  for (size_t r = 0; r + 1 < lines.size(); ++r) {
    for (size_t c = 0; c + 1 < lines.size(); ++c) {
      const uint32_t a = lines[r] * n + lines[c], b = lines[r] * n + lines[c + 1], c0 = lines[r + 1] * n + lines[c],
                     d = lines[r + 1] * n + lines[c + 1];
      indices.insert(indices.end(), {a, c0, b, b, c0, d});
    }
  }
  return indices;
}

shader::WaterSurfaceParams waterSurfaceParams(const scene::Scene& scene) {
  const scene::Water& w = scene.water;
  return shader::WaterSurfaceParams{
      .placement = {-0.5f * w.extent, w.level, -0.5f * w.extent, w.extent / float(w.grid)},
      .extinction = glm::vec4(w.absorption + w.scattering, w.ior),
      .scattering = glm::vec4(w.scattering, w.scatteringAnisotropy),
      .grid = {w.grid, w.scatteringShadowPieces, 0u, 0u},
  };
}

shader::GroundParams groundParams(const scene::Scene& scene) {
  const scene::Ground& g = scene.ground;
  const bool terrace = g.pattern == "terrace";
  // The coping's joints are as wide as the pavers'.
  return {.plane = {g.halfExtent, g.height, g.checkerSize, hasPool(scene) ? 0.5f * scene.water.extent : 0.0f},
          .albedoA = glm::vec4(g.albedoA, terrace ? 1.0f : 0.0f),
          .albedoB = glm::vec4(g.albedoB, 0.5f),  // running bond
          .tiles = {1.0f / g.paverWidth, 1.0f / g.paverDepth, 0.5f * g.jointWidth / g.paverWidth,
                    0.5f * g.jointWidth / g.paverDepth},
          .jointAlbedo = glm::vec4(g.jointAlbedo, terrace ? g.copingWidth : 0.0f),
          .copingAlbedo = glm::vec4(g.copingAlbedo, terrace ? g.terraceHalfExtent : 0.0f),
          .lawnAlbedo = glm::vec4(g.lawnAlbedo, 0.5f * g.jointWidth)};
}

namespace {

// Appends the quad a, b, c, d (counter-clockwise seen from its front) to a mesh.
void addQuad(scene::Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  const uint32_t base = uint32_t(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

}  // namespace

std::vector<scene::Mesh> sceneMeshes(const scene::Scene& scene, const sim::WaterState* water, float time) {
  std::vector<scene::Mesh> meshes;
  const shader::GroundParams g = groundParams(scene);
  const float e = g.plane.x, y = g.plane.y, hole = g.plane.w;
  // As ground.vert draws it: four trapezoids between the outer square and the hole.
  scene::Mesh ground{"ground", {}, {}};
  const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    const glm::vec2 o0 = corners[k] * e, o1 = corners[(k + 1) % 4] * e;
    const glm::vec2 i0 = corners[k] * hole, i1 = corners[(k + 1) % 4] * hole;
    addQuad(ground, {o0.x, y, o0.y}, {i0.x, y, i0.y}, {i1.x, y, i1.y}, {o1.x, y, o1.y});
  }
  meshes.push_back(std::move(ground));
  if (hasPool(scene)) {
    const PoolModel pool = poolModel(scene);
    const shader::PoolParams& p = pool.params;
    const float s = p.box.x, top = p.box.y, bottom = shader::poolBottom(p);
    scene::Mesh walls{"pool_walls", {}, {}};
    addQuad(walls, {-s, top, -s}, {-s, bottom, -s}, {s, bottom, -s}, {s, top, -s});
    addQuad(walls, {s, top, -s}, {s, bottom, -s}, {s, bottom, s}, {s, top, s});
    addQuad(walls, {s, top, s}, {s, bottom, s}, {-s, bottom, s}, {-s, top, s});
    addQuad(walls, {-s, top, s}, {-s, bottom, s}, {-s, bottom, -s}, {-s, top, -s});
    meshes.push_back(std::move(walls));
    // As pool_floor.vert draws it: the same grid and the same height function, bit for bit.
    scene::Mesh floor{"pool_floor", {}, waterGridIndices(kPoolFloorGrid)};
    for (uint32_t j = 0; j < kPoolFloorGrid; ++j) {
      for (uint32_t i = 0; i < kPoolFloorGrid; ++i) {
        const glm::vec2 xz = poolFloorVertexXz(p, i, j);
        floor.positions.push_back({xz.x, pool.floorVertices[size_t(j) * kPoolFloorGrid + i].w, xz.y});
      }
    }
    meshes.push_back(std::move(floor));
  }
  const scene::Scene placed = scene::sceneAt(scene, time);
  for (size_t i = 0; i < placed.spheres.size(); ++i)
    meshes.push_back(sphereMesh(placed.spheres[i], "sphere" + std::to_string(i)));
  for (size_t i = 0; i < placed.boxes.size(); ++i)
    meshes.push_back(boxMesh(placed.boxes[i], "box" + std::to_string(i)));
  if (water) {
    const shader::WaterSurfaceParams p = waterSurfaceParams(scene);
    const auto cells = sim::toCells(*water, scene.water.extent);
    scene::Mesh surface{"water", {}, waterGridIndices(water->n)};
    surface.positions.reserve(cells.size());
    for (const auto& c : cells)
      surface.positions.push_back({p.placement.x + c.x, p.placement.y + c.u, p.placement.z + c.z});
    meshes.push_back(std::move(surface));
  }
  return meshes;
}

WaterToTheWalls waterSurfaceToTheWalls(const scene::Scene& scene, const sim::WaterState& water) {
  const uint32_t n = water.n, side = n + 2;
  const shader::WaterSurfaceParams p = waterSurfaceParams(scene);
  const float h = p.placement.w;
  const auto cells = sim::toCells(water, scene.water.extent);
  const std::vector<glm::vec3> cellNormals = waterVertexNormals(water, scene.water.extent);
  WaterToTheWalls to{{"water to the walls", {}, waterGridIndices(side)}, {}};
  to.mesh.positions.reserve(size_t(side) * side);
  to.normals.reserve(size_t(side) * side);
  for (uint32_t j = 0; j < side; ++j) {
    for (uint32_t i = 0; i < side; ++i) {
      const size_t cell = size_t(std::clamp(j, 1u, n) - 1) * n + (std::clamp(i, 1u, n) - 1);
      // Vertex k of a row lies at (k - 1/2) h from the grid's corner, held within the walls.
      const float x = std::clamp(float(i) - 0.5f, 0.0f, float(n)) * h;
      const float z = std::clamp(float(j) - 0.5f, 0.0f, float(n)) * h;
      to.mesh.positions.push_back({p.placement.x + x, p.placement.y + cells[cell].u, p.placement.z + z});
      glm::vec3 normal = cellNormals[cell];
      if (i == 0 || i == side - 1) normal.x = 0.0f;
      if (j == 0 || j == side - 1) normal.z = 0.0f;
      to.normals.push_back(glm::normalize(normal));
    }
  }
  return to;
}

bool cameraOverWater(const scene::Scene& scene) {
  const glm::vec3 c = scene.camera.position;
  return shader::overWaterSquare(waterSurfaceParams(scene), glm::vec2(c.x, c.z));
}

bool apparentRefraction(const scene::Scene& scene) { return scene.render.refraction == "apparent"; }

namespace {

// The slots between the water's mesh and the walls, half a cell wide, and
// the camera's distance across each wall's plane to the near side of its slot.
struct Slots {
  float width;
  std::array<float, 4> across;
};

Slots slotsFrom(const scene::Scene& scene) {
  const glm::vec3 c = scene.camera.position;
  const shader::WaterSurfaceParams p = waterSurfaceParams(scene);
  const float slot = 0.5f * p.placement.w, size = float(p.grid.x) * p.placement.w;
  const float walls[] = {c.x - p.placement.x, c.x - (p.placement.x + size), c.z - p.placement.z,
                         c.z - (p.placement.z + size)};
  Slots slots{slot, {}};
  for (size_t w = 0; w < 4; ++w) slots.across[w] = std::abs(walls[w]) - slot;
  return slots;
}

}  // namespace

bool floorSeenOnlyThroughWater(const scene::Scene& scene, float waveHeight, float floorTop) {
  const glm::vec3 c = scene.camera.position;
  // Under the rim, away from the water, the camera is under the ground.
  if (apparentRefraction(scene) || cameraOverWater(scene) || !(c.y > scene.ground.height)) return false;
  const float lowest = scene.water.level - waveHeight, highest = scene.water.level + waveHeight;
  // How far a line must drop across a slot, the width of half a cell, to
  // show the floor through it: from over the rim down to the water, or from
  // the water down to the floor before it meets the wall.
  const float drop = std::min(scene.ground.height - highest, lowest - floorTop);
  if (!(drop > 0.0f)) return false;
  // A line from the camera reaches a wall's slot at the water (no lower than
  // its lowest) no steeper, across the wall, than the camera's height over
  // the water by its distance from the slot.
  const Slots slots = slotsFrom(scene);
  for (float across : slots.across) {
    if (!(across > 0.0f) || (c.y - lowest) * slots.width >= drop * across) return false;
  }
  return true;
}

float seenOnlyThroughWaterBelow(const scene::Scene& scene, float waveHeight) {
  const float lowest = scene.water.level - waveHeight;
  const Slots slots = slotsFrom(scene);
  float reach = 0.0f;
  for (float across : slots.across) reach = std::max(reach, (scene.camera.position.y - lowest) * slots.width / across);
  return lowest - 2.0f * reach;
}

bool hasWaterScattering(const scene::Scene& scene) {
  return scene.water.enabled && shader::waterScatters(glm::vec4(scene.water.scattering, 0.0f));
}

shader::CameraMedium cameraInAir() { return {glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f)}; }

shader::CameraMedium cameraMedium(const scene::Scene& scene, const sim::WaterState* water) {
  if (!water) return cameraInAir();
  const shader::WaterSurfaceParams p = waterSurfaceParams(scene);
  const glm::vec3 camera = scene.camera.position;
  const glm::vec4 quad = shader::gridQuadAt(p, glm::vec2(camera.x, camera.z));
  const auto u = [&](uint32_t i, uint32_t j) { return water->u[size_t(j) * water->n + i]; };
  const uint32_t i = uint32_t(quad.x), j = uint32_t(quad.y);
  const glm::vec4 corners(u(i, j), u(i + 1, j), u(i, j + 1), u(i + 1, j + 1));
  const bool under = shader::underWaterSurface(p, camera, corners, glm::vec2(quad.z, quad.w));
  if (!under) return cameraInAir();
  return {.extinction = glm::vec4(glm::vec3(p.extinction), 1.0f),
          .scattering = p.scattering,
          .water = glm::vec4(p.placement.y, p.extinction.w, float(p.grid.y), 0.0f)};
}

}  // namespace tp::render
