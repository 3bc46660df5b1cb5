#pragma once
// A sphere crossing the pool at a fraction of the wave speed: the case the
// wake's tests and its benchmark (tidepool bench wake) share.
#include <cstdint>

#include "gpu/context.hpp"
#include "scene/scene.hpp"
#include "sim/wake_measures.hpp"
#include "sim/water_params.hpp"
#include "sim/water_state.hpp"

namespace tp::sim {

struct WakeCase {
  uint32_t grid = 128;
  double speedFraction = 0.5;  // the sphere's speed over the wave speed
  bool submerged = false;      // fully under, its top kSubmergedClearance below the level; else half in
  double gridDamping = scene::Water{}.gridDamping;  // kappa, 1/s: the scenes' default
  SphereForcing forcing = SphereForcing::Column;
  // The default scene's pool and sphere: a 4 m square, c = 0.6 m/s,
  // gamma = 0.3/s, a sphere of 0.45 m crossing 2.8 m along x at 30 frames/s.
  double extent = 4.0, waveSpeed = 0.6, damping = 0.3, radius = 0.45, crossing = 2.8, frameTime = 1.0 / 30.0;
};

// How far below the level a submerged sphere's top runs, in metres.
inline constexpr double kSubmergedClearance = 0.05;

struct WakeResult {
  WaterState state;  // after the crossing, u relative to the rest level 0
  WakeMeasures measures;
  uint64_t steps = 0;
  double secondsPerStep = 0.0;  // wall, forcing and step, the submissions waited for
  // The water's own volume (heights times h^2 minus the sphere's submerged
  // volume) after the crossing, less before: zero but for float round-off.
  double volumeChange = 0.0;
  double submergedVolume = 0.0;  // the sphere's, below the level (closed form)
};

// Runs the crossing on `ctx` from still water: each step moves the sphere
// by its speed times dt (the case's forcing displaces the water), then steps.
WakeResult runWake(const gpu::Context& ctx, const WakeCase& c);

}  // namespace tp::sim
