// The ground's terrace and the pool's tiles (shared/surface_pattern.h)
// against exact answers: the share of grout, each tile's tone between its
// two albedos, the filter over whole tiles, the coping's band and its
// filtered edge, the lawn's mean; and the GPU's albedo against the CPU's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "gpu_test.hpp"
#include "pool_shader_points.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "shared/pool.h"
#include "shared/surface_pattern.h"

namespace tp::test {
namespace {

scene::Scene patternScene() {
  scene::Scene s = scene::defaultScene();
  s.ground.pattern = "terrace";
  s.pool.floorPattern = "tiles";
  s.pool.wallPattern = "tiles";
  // Grout unlike either tone, so a point's albedo says where it is.
  s.pool.groutAlbedo = glm::vec3(0.9f, 0.0f, 0.9f);
  s.ground.jointAlbedo = glm::vec3(0.0f, 0.0f, 0.9f);
  return s;
}

bool near(glm::vec3 a, glm::vec3 b, float tolerance) {
  return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

// Whether c lies on the segment from a to b (each channel between theirs).
bool between(glm::vec3 c, glm::vec3 a, glm::vec3 b) {
  const float e = 1e-6f;
  return glm::all(glm::greaterThanEqual(c, glm::min(a, b) - e)) && glm::all(glm::lessThanEqual(c, glm::max(a, b) + e));
}

}  // namespace

// Grout g wide round each tile of side t (grout included): a share
// 1 - (1 - g/t)^2 of the floor is grout. Counted on a fine grid over whole tiles.
TEST(SurfacePatternTest, GroutCoversItsExactShare) {
  const scene::Scene s = patternScene();
  const shader::GroundParams tiles = render::poolParams(s).tiles;
  const int perTile = 200, count = 5;
  int grout = 0, total = 0;
  for (int j = 0; j < perTile * count; ++j) {
    for (int i = 0; i < perTile * count; ++i) {
      const glm::vec2 p = (glm::vec2(i, j) + 0.5f) / float(perTile) * s.pool.tileSize;
      const glm::vec3 a = shader::groundAlbedo(tiles, p, glm::vec2(0.0f));
      grout += a == s.pool.groutAlbedo ? 1 : 0;
      ++total;
    }
  }
  const double f = s.pool.groutWidth / s.pool.tileSize;
  const double exact = 1.0 - (1.0 - f) * (1.0 - f);
  // The grid resolves the grout to a 200th of a tile on each side.
  EXPECT_NEAR(double(grout) / total, exact, 2.0 / perTile);
  EXPECT_GT(exact, 4.0 / perTile);
}

// Each tile has one tone between tile_albedo_a and _b, the same over the
// tile; neighbours differ.
TEST(SurfacePatternTest, EachTileHasItsOwnToneBetweenTheTwo) {
  const scene::Scene s = patternScene();
  const shader::GroundParams tiles = render::poolParams(s).tiles;
  std::set<float> tones;
  for (int j = -4; j < 4; ++j) {
    for (int i = -4; i < 4; ++i) {
      const glm::vec2 centre = (glm::vec2(i, j) + 0.5f) * s.pool.tileSize;
      const glm::vec3 a = shader::groundAlbedo(tiles, centre, glm::vec2(0.0f));
      const glm::vec3 corner = shader::groundAlbedo(tiles, centre + 0.4f * s.pool.tileSize, glm::vec2(0.0f));
      EXPECT_EQ(a, corner) << "tile " << i << ", " << j;
      EXPECT_TRUE(between(a, s.pool.tileAlbedoA, s.pool.tileAlbedoB)) << "tile " << i << ", " << j;
      tones.insert(a.x);
    }
  }
  EXPECT_GT(tones.size(), 48u);
}

// A footprint of whole tiles (or pavers) averages the pattern exactly: the
// box filter over whole periods is the mean, and the tones fade to theirs.
TEST(SurfacePatternTest, WholeTilesFilterToTheMean) {
  const scene::Scene s = patternScene();
  const shader::PoolParams pool = render::poolParams(s);
  const glm::vec3 tileMean = shader::patternMeanAlbedo(pool.tiles);
  const glm::vec3 paverMean = shader::patternMeanAlbedo(pool.ground);
  // The closed form: grout on 1 - (1 - g/t)^2, the mean tone on the rest.
  const float onTile = std::pow(1.0f - s.pool.groutWidth / s.pool.tileSize, 2.0f);
  const glm::vec3 exact =
      s.pool.groutAlbedo + (0.5f * (s.pool.tileAlbedoA + s.pool.tileAlbedoB) - s.pool.groutAlbedo) * onTile;
  EXPECT_TRUE(near(tileMean, exact, 1e-6f));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  for (int k = 0; k < 200; ++k) {
    const glm::vec2 p(u(rng), u(rng));
    const glm::vec3 floor = shader::groundAlbedo(pool.tiles, p, glm::vec2(3.0f * s.pool.tileSize));
    ASSERT_TRUE(near(floor, tileMean, 2e-5f)) << p.x << ", " << p.y << ": " << floor.x << " vs " << tileMean.x;
    // On the terrace, clear of the coping and the lawn: pavers over 2 x 3 of them.
    const glm::vec2 q = glm::vec2(3.8f, 0.0f) + 0.2f * glm::vec2(u(rng), u(rng));
    const glm::vec3 paved =
        shader::groundAlbedo(pool.ground, q, glm::vec2(2.0f * s.ground.paverWidth, 3.0f * s.ground.paverDepth));
    ASSERT_TRUE(near(paved, paverMean, 2e-5f)) << q.x << ", " << q.y;
  }
}

// Round the pool: the coping's stones from its edge to coping_width out,
// their albedo or their joints'; the terrace's pavers from there; the lawn
// past the terrace. The band's edge is box-filtered: a footprint centred on
// it is half coping, half pavers.
TEST(SurfacePatternTest, CopingAndLawnLieWhereTheSceneSays) {
  const scene::Scene s = patternScene();
  const shader::GroundParams g = render::groundParams(s);
  const float hole = 0.5f * s.water.extent, coping = s.ground.copingWidth;
  const glm::vec2 zero(0.0f);
  // Whole stones along each side, joints on the pool's corners.
  const float stones = std::max(1.0f, std::round(2.0f * hole / (shader::kCopingStoneLength * coping)));
  const float stone = 2.0f * hole / stones;
  EXPECT_NEAR(stone / coping, shader::kCopingStoneLength, 0.5f * stone / coping / stones);
  for (const float side : {-1.0f, 1.0f}) {
    // On a stone's middle along the edge.
    const float along = -hole + 1.5f * stone, joint = -hole + stone;
    const glm::vec3 onCoping = shader::groundAlbedo(g, {side * (hole + 0.5f * coping), along}, zero);
    EXPECT_EQ(onCoping, s.ground.copingAlbedo);
    EXPECT_EQ(shader::groundAlbedo(g, {along, side * (hole + 0.5f * coping)}, zero), s.ground.copingAlbedo);
    // A stone's joint, and the stones' joints do not reach the terrace.
    EXPECT_EQ(shader::groundAlbedo(g, {side * (hole + 0.5f * coping), joint}, zero), s.ground.jointAlbedo);
    // The corner is one stone, its joints on the lines of the pool's edges.
    EXPECT_EQ(shader::groundAlbedo(g, {side * (hole + 0.5f * coping), hole + 0.4f * coping}, zero),
              s.ground.copingAlbedo);
    EXPECT_EQ(shader::groundAlbedo(g, {side * (hole + 0.5f * coping), hole + 0.001f}, zero), s.ground.jointAlbedo);
    const glm::vec2 terrace(side * (hole + coping + 1.0f), 0.3f);
    EXPECT_EQ(shader::groundAlbedo(g, terrace, zero), shader::patternAlbedo(g, terrace, zero));
    // Half a metre wide across the edge: half on each side.
    const glm::vec2 edge(side * (hole + coping), along);
    const glm::vec2 footprint(0.5f, 0.0f);
    const glm::vec3 filtered = shader::groundAlbedo(g, edge, footprint);
    const glm::vec3 halves = 0.5f * s.ground.copingAlbedo + 0.5f * shader::patternAlbedo(g, edge, footprint);
    EXPECT_TRUE(near(filtered, halves, 1e-5f)) << filtered.x << " vs " << halves.x;
  }
  // The lawn: green, within kLawnVariation of lawn_albedo; seen from afar its mean.
  for (float x = s.ground.terraceHalfExtent + 0.5f; x < 60.0f; x += 3.7f) {
    const glm::vec3 lawn = shader::groundAlbedo(g, {x, 0.7f * x}, zero);
    EXPECT_TRUE(between(lawn, s.ground.lawnAlbedo, s.ground.lawnAlbedo * (1.0f - shader::kLawnVariation))) << x;
  }
  const glm::vec3 far = shader::groundAlbedo(g, {50.0f, 20.0f}, glm::vec2(10.0f));
  EXPECT_TRUE(near(far, s.ground.lawnAlbedo * (1.0f - 0.5f * shader::kLawnVariation), 1e-6f));
}

// The GPU's albedo equals the CPU's bit for bit: ground, floor and walls,
// point-sampled and filtered, over the pool, the coping, the terrace and the lawn.
TEST_F(GpuTest, SurfacePatternGpuMatchesCpu) {
  const shader::PoolParams pool = render::poolParams(patternScene());
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> where(-9.0f, 9.0f), width(0.0f, 0.6f);
  std::vector<glm::vec4> points(4096);
  for (size_t k = 0; k < points.size(); ++k) {
    const bool pointSampled = k % 3 == 0;
    points[k] = {where(rng), where(rng), pointSampled ? 0.0f : width(rng), pointSampled ? 0.0f : width(rng)};
  }
  const uint32_t count = uint32_t(points.size());
  const auto gpuValues = poolShaderAtPoints(ctx(), "test_surface_pattern.comp", points, pool, 3);
  int mismatches = 0;
  float worst = 0.0f;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec2 p(points[i]), footprint(points[i].z, points[i].w);
    const glm::vec3 cpu[3] = {shader::groundAlbedo(pool.ground, p, footprint),
                              shader::groundAlbedo(pool.tiles, p, footprint),
                              shader::poolWallAlbedo(pool, p, footprint)};
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 gpu(gpuValues[3 * i + k]);
      const glm::vec3 d = glm::abs(gpu - cpu[k]);
      worst = std::max({worst, d.x, d.y, d.z});
      if (gpu != cpu[k] && ++mismatches <= 3) {
        ADD_FAILURE() << "surface " << k << " at (" << p.x << ", " << p.y << ") over (" << footprint.x << ", "
                      << footprint.y << "): GPU " << gpu.x << " CPU " << cpu[k].x;
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << "largest difference " << worst;
}

}  // namespace tp::test
