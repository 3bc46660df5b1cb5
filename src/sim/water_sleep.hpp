#pragma once
#include <cstdint>

#include "scene/scene.hpp"
#include "sim/water_stats.hpp"

namespace tp::sim {

// When the renderer may stop simulating the water and draw its last state.
//
// The error bound: the energy the stats measure, per unit area e, bounds the
// surface's RMS slope by sqrt(2 e) / c (its potential part is c^2 |grad u|^2 / 2),
// and, as the pool's longest wave is twice its width L (Poincare), its RMS
// height about the mean by (L / pi) sqrt(2 e) / c. Undisturbed, the energy
// never grows (damping only takes it away), so neither does either bound:
// freezing the state at energy e differs from simulating on by at most twice
// each. The threshold sets the slope bound to kSleepSlope.
struct SleepRule {
  double energyPerArea = 0.0;  // sleep below this (m^3/s^2 per m^2, the stats' unit over the area)
  uint32_t quietFrames = 0;    // ... measured on this many frames in a row
};

// RMS slope (radians, of the surface normal) that a sleeping frame may differ by, at most twice this.
inline constexpr double kSleepSlope = 5e-5;

SleepRule sleepRule(const scene::Water& water);

class WaterSleep {
 public:
  explicit WaterSleep(SleepRule rule) : rule_(rule) {}
  // A new start: water exactly at rest (zero energy: flat, still) sleeps at
  // once, since undisturbed it stays so to the bit.
  void restart(const WaterStats& stats);
  void wake();
  // The energy per unit area of a simulated frame's water.
  void observe(double energyPerArea);
  bool asleep() const { return asleep_; }
  // Its count of quiet frames in a row: with asleep(), what a checkpoint
  // keeps (Renderer::checkpoint) and resume() puts back.
  uint32_t quietFrames() const { return quiet_; }
  void resume(uint32_t quietFrames, bool asleep) {
    quiet_ = quietFrames;
    asleep_ = asleep;
  }

 private:
  SleepRule rule_;
  uint32_t quiet_ = 0;
  bool asleep_ = false;
};

}  // namespace tp::sim
