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
  // Wrap: the grid wraps round and the sphere with it, to cross it again and
  // again (its wake then settles into sim/steady_wake.hpp's).
  Boundary boundary = Boundary::Clamp;
  double spreadDepthFactor = kSpreadDepthFactor;  // the spread forcing's widening per metre of depth
  bool widenNearWaveSpeed = true;                 // and near the wave speed (wakeWidening)
  double maxSlope = 0.0;                          // the slope limiter (water.max_slope); 0: off
  // The default scene's pool, water and sphere (a 4 m square, c = 0.6 m/s,
  // gamma = 0.3/s, 30 frames/s, a sphere of 0.4 m), the sphere crossing 2.8 m along x.
  double extent = scene::Water{}.extent, waveSpeed = scene::Water{}.waveSpeed, damping = scene::Water{}.damping,
         radius = scene::Scene{}.spheres.front().radius, crossing = 2.8, frameTime = scene::Water{}.frameTime;
};

// How far below the level a submerged sphere's top runs, in metres.
inline constexpr double kSubmergedClearance = 0.05;

struct WakeResult {
  WaterState state;  // after the crossing, u relative to the rest level 0
  WakeMeasures measures;
  uint64_t steps = 0;
  double dt = 0.0;              // seconds a step
  glm::vec3 endCentre{};        // where the sphere stands after the last step
  double secondsPerStep = 0.0;  // wall, forcing and step, the submissions waited for
  // The water's own volume (heights times h^2 minus the sphere's submerged
  // volume) after the crossing, less before: zero but for float round-off.
  double volumeChange = 0.0;
  double submergedVolume = 0.0;  // the sphere's, below the level (closed form)
};

// The water the case's crossing runs in.
WaterParams waterParams(const WakeCase& c);

// Runs the crossing on `ctx` from still water: each step moves the sphere
// by its speed times dt (the case's forcing displaces the water), then steps.
WakeResult runWake(const gpu::Context& ctx, const WakeCase& c);

}  // namespace tp::sim
