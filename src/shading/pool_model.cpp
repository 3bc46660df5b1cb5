#include "shading/pool_model.hpp"

#include <algorithm>
#include <utility>

#include "shading/water_model.hpp"
#include "shared/shading.h"

namespace tp::render {

glm::vec2 poolFloorVertexXz(const shader::PoolParams& pool, uint32_t i, uint32_t j) {
  const glm::vec2 uv = glm::vec2(float(i), float(j)) / float(kPoolFloorGrid - 1);
  return (uv * 2.0f - 1.0f) * pool.box.x;
}

float causticsReach(const scene::Scene& scene, uint32_t texels) {
  const float half = 0.5f * scene.water.extent;
  return half - half / float(texels);
}

namespace {

float wallPatternCode(const std::string& pattern) {
  if (pattern == "brick") return shader::kPoolWallBrick;
  if (pattern == "tiles") return shader::kPoolWallTiles;
  return shader::kPoolWallPlain;
}

}  // namespace

bool hasBrickWalls(const scene::Scene& scene) { return hasPool(scene) && scene.pool.wallPattern == "brick"; }

bool hasTiledSurface(const scene::Scene& scene) {
  const scene::Pool& p = scene.pool;
  return scene.ground.pattern == "terrace" ||
         (hasPool(scene) && (p.floorPattern == "tiles" || p.wallPattern == "tiles"));
}

PoolModel poolModel(const scene::Scene& scene) {
  const scene::Pool& p = scene.pool;
  const scene::Terrain& t = scene.terrain;
  shader::PoolParams params{
      .box = {0.5f * scene.water.extent, scene.ground.height, p.depth, t.amplitude},
      .terrain = {t.frequency, t.persistence, 0.0f, 0.0f},
      .noise = {t.octaves, t.seed, kPoolFloorGrid, 0u},
      .wallAlbedo = glm::vec4(p.wallAlbedo, wallPatternCode(p.wallPattern)),
      // Stacked square tiles, or the checker; no coping or lawn.
      .tiles = {.plane = {0.0f, 0.0f, p.tileSize, 0.0f},
                .albedoA = glm::vec4(p.tileAlbedoA, p.floorPattern == "tiles" ? 1.0f : 0.0f),
                .albedoB = glm::vec4(p.tileAlbedoB, 0.0f),
                .tiles = glm::vec4(glm::vec2(1.0f / p.tileSize), glm::vec2(0.5f * p.groutWidth / p.tileSize)),
                .jointAlbedo = glm::vec4(p.groutAlbedo, 0.0f),
                .copingAlbedo = glm::vec4(0.0f),
                .lawnAlbedo = glm::vec4(0.0f)},
      // The joint is mortarFraction of the brick height wide, between courses and between bricks.
      .brick = {1.0f / p.brickWidth, 1.0f / p.brickHeight, 0.5f * p.mortarFraction * p.brickHeight / p.brickWidth,
                0.5f * p.mortarFraction},
      .brickAlbedo = glm::vec4(p.brickAlbedo, p.dirt),
      .mortarAlbedo = glm::vec4(p.mortarAlbedo, 0.0f),
      .wallGloss = {p.wallSpecular, p.wallRoughness, 0.0f, 0.0f},
      .water = {scene.water.level, scene.water.ior, causticsReach(scene, kCausticsSize),
                scene.water.enabled ? float(scene.water.grid) : 0.0f},
      .extinction =
          glm::vec4(scene.water.absorption + scene.water.scattering, float(scene.water.scatteringShadowPieces)),
      .scattering = glm::vec4(scene.water.scattering, scene.water.scatteringAnisotropy),
      .ground = groundParams(scene),
  };
  std::vector<glm::vec4> vertices;
  vertices.reserve(size_t(kPoolFloorGrid) * kPoolFloorGrid);
  for (uint32_t j = 0; j < kPoolFloorGrid; ++j) {
    for (uint32_t i = 0; i < kPoolFloorGrid; ++i) {
      const glm::vec2 xz = poolFloorVertexXz(params, i, j);
      vertices.emplace_back(shader::poolFloorNormal(params, xz, shader::kPoolFloorNormalSpacing),
                            shader::poolFloorHeight(params, xz));
    }
  }
  // The slab the floor mesh lies in, where the water's rays walk its cells.
  params.terrain.z = params.terrain.w = vertices.front().w;
  for (const glm::vec4& v : vertices) {
    params.terrain.z = std::min(params.terrain.z, v.w);
    params.terrain.w = std::max(params.terrain.w, v.w);
  }
  return {params, std::move(vertices)};
}

shader::PoolParams poolParams(const scene::Scene& scene) { return poolModel(scene).params; }

}  // namespace tp::render
