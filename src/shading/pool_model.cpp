#include "shading/pool_model.hpp"

namespace tp::render {

shader::PoolParams poolParams(const scene::Scene& scene) {
  const scene::Pool& p = scene.pool;
  const scene::Terrain& t = scene.terrain;
  return shader::PoolParams{
      .box = {0.5f * scene.water.extent, scene.ground.height, p.depth, t.amplitude},
      .terrain = {t.frequency, t.persistence, 0.0f, 0.0f},
      .noise = {t.octaves, t.seed, kPoolMarchSteps, kPoolBisections},
      .wallAlbedo = glm::vec4(p.wallAlbedo, p.wallPattern == "brick" ? 1.0f : 0.0f),
      .tiles = {.plane = {0.0f, 0.0f, p.tileSize, 0.0f},
                .albedoA = glm::vec4(p.tileAlbedoA, 0.0f),
                .albedoB = glm::vec4(p.tileAlbedoB, 0.0f)},
      // The joint is mortarFraction of the brick height wide, between courses and between bricks.
      .brick = {1.0f / p.brickWidth, 1.0f / p.brickHeight, 0.5f * p.mortarFraction * p.brickHeight / p.brickWidth,
                0.5f * p.mortarFraction},
      .brickAlbedo = glm::vec4(p.brickAlbedo, p.dirt),
      .mortarAlbedo = glm::vec4(p.mortarAlbedo, 0.0f),
      .wallGloss = {p.wallSpecular, p.wallRoughness, 0.0f, 0.0f},
  };
}

}  // namespace tp::render
