// The water's cast into the pool (shared/pool_trace.h) against the reference
// tracer's BVH of the same floor mesh and walls: the same first hit, for rays
// in every direction down from points of the water, over terrain and over a
// flat floor (where the march it replaced slipped through and showed the walls).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "reference/reference_scene.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/pool_trace.h"

namespace tp::test {
namespace {

struct CastErrors {
  double worstDistance = 0.0;  // metres, over rays that both hit
  int floorDisagreements = 0;  // rays where one says floor and the other a wall
  int rays = 0;
};

CastErrors castAgainstBvh(const scene::Scene& s, int rays) {
  std::vector<scene::Mesh> pool;
  for (auto& m : render::sceneMeshes(s, nullptr, 0.0f)) {
    if (m.name == "pool_floor" || m.name == "pool_walls") pool.push_back(std::move(m));
  }
  const render::ReferenceScene exact(pool, {});
  const render::PoolModel model = render::poolModel(s);
  const shader::PoolParams& params = model.params;
  const std::vector<glm::vec4>& vertices = model.floorVertices;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  CastErrors e;
  const float half = 0.5f * s.water.extent;
  for (int k = 0; k < rays; ++k) {
    const glm::vec3 origin(0.98f * half * unit(rng), s.water.level + 0.05f * unit(rng), 0.98f * half * unit(rng));
    glm::vec3 dir(unit(rng), -std::abs(unit(rng)) - 0.05f, unit(rng));
    dir = glm::normalize(dir);
    const render::ReferenceHit truth = exact.intersect(origin, dir, 0.0f);
    if (!truth.hit()) continue;
    const shader::PoolHit cast = shader::tracePool(params, origin, dir, vertices.data());
    const bool truthOnFloor = pool[size_t(truth.mesh)].name == "pool_floor";
    ++e.rays;
    // A ray through the floor's seam with a wall may fairly be given to either.
    if (cast.floor != truthOnFloor && std::abs(cast.distance - truth.distance) > 1e-4f) ++e.floorDisagreements;
    e.worstDistance = std::max(e.worstDistance, double(std::abs(cast.distance - truth.distance)));
  }
  return e;
}

TEST(PoolTrace, MeetsTheFloorMeshWhereTheReferenceDoes) {
  const scene::Scene s = scene::defaultScene();
  const CastErrors e = castAgainstBvh(s, 20000);
  std::printf("terrain: %d rays, worst distance error %.3g m, %d floor/wall disagreements\n", e.rays, e.worstDistance,
              e.floorDisagreements);
  EXPECT_GT(e.rays, 19000);
  EXPECT_EQ(e.floorDisagreements, 0);
  // Float round-off over a few metres of ray.
  EXPECT_LT(e.worstDistance, 1e-4);
}

TEST(PoolTrace, MeetsAFlatFloorEverywhere) {
  scene::Scene s = scene::defaultScene();
  s.terrain.amplitude = 0.0f;
  const CastErrors e = castAgainstBvh(s, 20000);
  std::printf("flat floor: %d rays, worst distance error %.3g m, %d floor/wall disagreements\n", e.rays,
              e.worstDistance, e.floorDisagreements);
  EXPECT_GT(e.rays, 19000);
  EXPECT_EQ(e.floorDisagreements, 0);
  EXPECT_LT(e.worstDistance, 1e-4);
}

// The floor's shading normal is its vertex normals interpolated over each
// triangle (as the rasterizer does where the floor is drawn) rather than the
// terrain function's own normal at the point: the difference, measured over
// the default terrain, is the shading approximation the mesh makes.
TEST(PoolTrace, MeshNormalsFollowTheTerrainsNormal) {
  const scene::Scene s = scene::defaultScene();
  const render::PoolModel pool = render::poolModel(s);
  const shader::PoolParams& params = pool.params;
  const std::vector<glm::vec4>& vertices = pool.floorVertices;
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  double worst = 0.0, sum = 0.0;
  constexpr int kPoints = 20000;
  for (int k = 0; k < kPoints; ++k) {
    const glm::vec2 xz(params.box.x * unit(rng), params.box.x * unit(rng));
    const glm::vec3 mesh = shader::poolFloorMeshNormal(params, xz, vertices.data());
    const glm::vec3 exact = shader::poolFloorNormal(params, xz, shader::kPoolFloorNormalSpacing);
    const double degrees = glm::degrees(std::acos(std::clamp(double(glm::dot(mesh, exact)), -1.0, 1.0)));
    worst = std::max(worst, degrees);
    sum += degrees;
  }
  std::printf("mesh normals against the terrain's: mean %.3f, worst %.3f degrees\n", sum / kPoints, worst);
  // At a vertex they are the same normal.
  const glm::vec3 atVertex = shader::poolFloorMeshNormal(params, glm::vec2(-params.box.x), vertices.data());
  EXPECT_LT(glm::length(atVertex - glm::vec3(vertices.front())), 1e-6f);
  // The finest octave's lattice is 5 cells wide: within a cell the terrain's
  // normal turns by little, and its kinks fall inside cells.
  EXPECT_LT(sum / kPoints, 1.0);
}

}  // namespace
}  // namespace tp::test
