// The pool walls' brick pattern (shared/brick.h, shared/pool.h) against exact
// answers: the share of the wall that is mortar, the half-brick shift of odd
// courses, the filter over whole bricks; and the GPU's albedo against the CPU's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "gpu_test.hpp"
#include "pool_shader_points.hpp"
#include "shading/pool_model.hpp"
#include "shared/pool.h"

namespace tp::test {
namespace {

scene::Scene brickScene() {
  scene::Scene s = scene::defaultScene();
  s.pool.wallPattern = "brick";
  s.pool.brickWidth = 0.25f;
  s.pool.brickHeight = 0.075f;
  s.pool.mortarFraction = 0.2f;
  return s;
}

// Point-sampled: 1 on brick, 0 on mortar, at wall point (metres).
float onBrick(const shader::PoolParams& p, glm::vec2 wall) {
  return shader::brickFraction(wall * glm::vec2(p.brick), glm::vec2(0.0f), glm::vec2(p.brick.z, p.brick.w));
}

}  // namespace

// The joint is m = mortar_fraction * brick height wide, round each brick of
// W x H (joints included): a share 1 - (1 - m/W)(1 - m/H) of the wall is
// mortar. Counted at the centres of an Nu x Nv grid over two courses (the
// pattern's period), offset from the joints: each course's brick part is at
// most two intervals along (error under 2 cells) times one down (under 1
// cell), so the count is within 2/Nu + 1/Nv of the exact share.
TEST(Brick, MortarShareOfTheWallIsTheAnalyticShare) {
  const scene::Scene s = brickScene();
  const shader::PoolParams p = render::poolParams(s);
  const double w = s.pool.brickWidth, h = s.pool.brickHeight, m = s.pool.mortarFraction * h;
  const double exact = 1.0 - (1.0 - m / w) * (1.0 - m / h);
  const int nu = 1999, nv = 1601;
  const glm::dvec2 origin(0.0123, 0.0371);
  long mortar = 0;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const glm::dvec2 wall = origin + glm::dvec2((i + 0.5) * w / nu, (j + 0.5) * 2.0 * h / nv);
      if (onBrick(p, glm::vec2(wall)) == 0.0f) ++mortar;
    }
  }
  const double measured = double(mortar) / (double(nu) * nv);
  EXPECT_NEAR(measured, exact, 2.0 / nu + 1.0 / nv);
  std::printf("mortar share: measured %.6f, exact %.6f (bound %.1e)\n", measured, exact, 2.0 / nu + 1.0 / nv);
}

// Head joints (between bricks) are centred on multiples of the brick width
// along even courses and half a brick further along odd ones: at a joint's
// centre the wall is mortar, just past the joint's half-width on either side
// it is brick.
TEST(Brick, OddCoursesAreShiftedHalfABrick) {
  const scene::Scene s = brickScene();
  const shader::PoolParams p = render::poolParams(s);
  const float w = s.pool.brickWidth, h = s.pool.brickHeight, halfJoint = 0.5f * s.pool.mortarFraction * h;
  const float clear = halfJoint + 0.02f * w;
  for (int course = 0; course < 6; ++course) {
    const float down = (course + 0.5f) * h;  // mid-course, away from the bed joints
    const float shift = course % 2 == 1 ? 0.5f * w : 0.0f;
    for (int k = -3; k <= 3; ++k) {
      const float joint = k * w - shift;
      EXPECT_EQ(onBrick(p, {joint, down}), 0.0f) << "course " << course << " joint " << k;
      EXPECT_EQ(onBrick(p, {joint - clear, down}), 1.0f) << "course " << course << " joint " << k;
      EXPECT_EQ(onBrick(p, {joint + clear, down}), 1.0f) << "course " << course << " joint " << k;
      // Half a brick from a joint of this course: the middle of a brick here,
      // and a joint of the course next to it.
      EXPECT_EQ(onBrick(p, {joint + 0.5f * w, down}), 1.0f);
      EXPECT_EQ(onBrick(p, {joint + 0.5f * w, down + h}), 0.0f);
    }
    // The bed joint between this course and the next.
    EXPECT_EQ(onBrick(p, {0.3f * w, (course + 1) * h}), 0.0f);
  }
}

// A footprint of one whole brick along and one course down holds exactly the
// brick share (1 - m/W)(1 - m/H), wherever it is centred.
TEST(Brick, FootprintOfAWholeBrickHoldsTheBrickShare) {
  const scene::Scene s = brickScene();
  const shader::PoolParams p = render::poolParams(s);
  const double w = s.pool.brickWidth, h = s.pool.brickHeight, m = s.pool.mortarFraction * h;
  const double exact = (1.0 - m / w) * (1.0 - m / h);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> along(-2.0f, 2.0f), down(0.0f, 1.2f);
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const glm::vec2 q = glm::vec2(along(rng), down(rng)) * glm::vec2(p.brick);
    const float f = shader::brickFraction(q, glm::vec2(1.0f), glm::vec2(p.brick.z, p.brick.w));
    worst = std::max(worst, std::abs(double(f) - exact));
  }
  EXPECT_LT(worst, 1e-5) << "float round-off of coordinates up to ~30 brick units";
}

// Plain walls are the wall albedo, everywhere.
TEST(Brick, PlainWallsAreTheWallAlbedo) {
  scene::Scene s = brickScene();
  s.pool.wallPattern = "plain";
  const shader::PoolParams p = render::poolParams(s);
  for (float x : {-1.3f, 0.2f, 1.9f})
    EXPECT_EQ(shader::poolWallAlbedo(p, {x, 0.4f}, glm::vec2(0.0f)), s.pool.wallAlbedo);
}

using BrickGpuTest = GpuTest;

TEST_F(BrickGpuTest, GpuAndCpuWallAlbedoAgreeToTheBit) {
  const shader::PoolParams pool = render::poolParams(brickScene());
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> along(-2.0f, 2.0f), down(0.0f, 1.4f);
  std::vector<glm::vec2> points(4096);
  for (auto& q : points) q = {along(rng), down(rng)};
  const uint32_t count = uint32_t(points.size());
  const auto gpuValues = poolShaderAtPoints(ctx(), "test_brick.comp", points, pool, 1);
  int mismatches = 0, mortar = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 cpu = shader::poolWallAlbedo(pool, points[i], glm::vec2(0.0f));
    if (glm::vec3(gpuValues[i]) != cpu && ++mismatches <= 3) {
      ADD_FAILURE() << "at (" << points[i].x << ", " << points[i].y << "): GPU " << gpuValues[i].x << " CPU " << cpu.x;
    }
    if (onBrick(pool, points[i]) == 0.0f) ++mortar;
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(mortar, 100);  // both brick and mortar were compared
}

}  // namespace tp::test
