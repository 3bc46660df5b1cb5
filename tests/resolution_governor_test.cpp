// The viewer's dynamic resolution (viewer/resolution_governor) against a
// frame whose time is a closed form of its size, t = fixed + per-pixel cost:
// it settles where that time is within its hysteresis band of the target,
// without changing size again, stays at full size when that is fast enough,
// and goes no smaller than its smallest scale when nothing is.
#include <gtest/gtest.h>

#include "viewer/resolution_governor.hpp"

namespace tp::test {
namespace {

struct CostModel {
  double fixedSeconds;
  double secondsPerPixel;
  double at(glm::uvec2 size) const { return fixedSeconds + secondsPerPixel * size.x * size.y; }
};

struct Outcome {
  glm::uvec2 size;
  uint32_t changes = 0;
  uint32_t lastChange = 0;  // the frame of the last change
};

Outcome run(app::ResolutionGovernor& governor, const CostModel& cost, uint32_t frames) {
  Outcome r;
  for (uint32_t f = 0; f < frames; ++f) {
    if (governor.frameShown(cost.at(governor.size()))) {
      ++r.changes;
      r.lastChange = f;
    }
  }
  r.size = governor.size();
  return r;
}

constexpr glm::uvec2 kFull{1280, 720};

TEST(ResolutionGovernor, SettlesWhereTheFrameTimeMeetsTheTarget) {
  // 200 ms at 1280x720, 4 ms of it fixed: a 30 fps target needs about a sixth of the pixels.
  const CostModel cost{0.004, 0.196 / (1280.0 * 720.0)};
  app::ResolutionGovernor governor(kFull, 30.0);
  const Outcome r = run(governor, cost, 300);
  const double t = cost.at(r.size), budget = 1.0 / 30.0;
  std::printf("settled at %ux%u, %.1f ms a frame, after %u changes (the last at frame %u)\n", r.size.x, r.size.y,
              1e3 * t, r.changes, r.lastChange);
  const app::GovernorSettings settings;
  EXPECT_LE(t, settings.shrink * budget);
  EXPECT_GE(t, settings.grow * budget);
  EXPECT_LE(r.changes, 3u);
  EXPECT_LT(r.lastChange, 60u);
  EXPECT_EQ(r.size.x % 8, 0u);
  EXPECT_EQ(r.size.y % 8, 0u);
  // The aspect within a step of 8 pixels.
  EXPECT_NEAR(double(r.size.x) / r.size.y, 16.0 / 9.0, 8.0 / r.size.y);
}

TEST(ResolutionGovernor, StaysAtFullSizeWhenFastEnough) {
  const CostModel cost{0.002, 0.020 / (1280.0 * 720.0)};
  app::ResolutionGovernor governor(kFull, 30.0);
  const Outcome r = run(governor, cost, 300);
  EXPECT_EQ(r.changes, 0u);
  EXPECT_EQ(r.size, kFull);
}

TEST(ResolutionGovernor, GoesNoSmallerThanItsSmallestScale) {
  // 50 ms fixed: no size meets 30 fps.
  const CostModel cost{0.050, 0.200 / (1280.0 * 720.0)};
  app::ResolutionGovernor governor(kFull, 30.0);
  const Outcome r = run(governor, cost, 300);
  EXPECT_EQ(r.size, (glm::uvec2{160, 88}));
}

TEST(ResolutionGovernor, GrowsBackWhenTheFramesGetCheaper) {
  app::ResolutionGovernor governor(kFull, 30.0);
  const Outcome slow = run(governor, {0.004, 0.396 / (1280.0 * 720.0)}, 200);
  ASSERT_LT(slow.size.x, kFull.x / 2);
  // A cheaper scene: a third of the per-pixel cost.
  const CostModel cheap{0.004, 0.132 / (1280.0 * 720.0)};
  const Outcome fast = run(governor, cheap, 200);
  EXPECT_GT(fast.size.x, slow.size.x);
  const double t = cheap.at(fast.size), budget = 1.0 / 30.0;
  EXPECT_LE(t, 1.05 * budget);
  EXPECT_GE(t, 0.7 * budget);
}

TEST(ResolutionGovernor, RefusesATargetThatIsNotPositive) {
  EXPECT_THROW(app::ResolutionGovernor(kFull, 0.0), std::invalid_argument);
  EXPECT_THROW(app::ResolutionGovernor(kFull, -5.0), std::invalid_argument);
}

}  // namespace
}  // namespace tp::test
