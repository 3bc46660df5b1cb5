#include "sim/water_sleep.hpp"

namespace tp::sim {

namespace {
// The energy only falls when nothing disturbs the water, so one frame under
// the threshold would do; a few guard against the float sums' rounding.
constexpr uint32_t kQuietFrames = 3;
}  // namespace

SleepRule sleepRule(const scene::Water& water) {
  const double c = water.waveSpeed;
  return {0.5 * (kSleepSlope * c) * (kSleepSlope * c), kQuietFrames};
}

void WaterSleep::restart(const WaterStats& stats) {
  quiet_ = 0;
  asleep_ = stats.energy == 0.0 && stats.maxAbsV == 0.0;
}

void WaterSleep::wake() {
  quiet_ = 0;
  asleep_ = false;
}

void WaterSleep::observe(double energyPerArea) {
  quiet_ = energyPerArea <= rule_.energyPerArea ? quiet_ + 1 : 0;
  if (quiet_ >= rule_.quietFrames) asleep_ = true;
}

}  // namespace tp::sim
