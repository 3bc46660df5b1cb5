#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tp::sim {

enum class Boundary { Clamp, Wrap };
enum class Scheme { Symplectic, Explicit };
// How a moving sphere displaces the water: each column by the sphere's volume
// within it (shared/sphere_column.h), or that volume spread over the surface
// as the flow around the body lifts it (shared/sphere_spread.h).
enum class SphereForcing { Column, Spread };

// The spread forcing's widening: a body d below the surface lifts a bump of
// deviation kSpreadDepthFactor * d more. A source at depth d under a free
// surface lifts it as the Poisson kernel d / (2 pi (rho^2 + d^2)^1.5), whose
// half maximum lies at rho = 0.766 d; a Gaussian's lies at 1.177 sigma.
inline constexpr double kSpreadDepthFactor = 0.766 / 1.177;

// A sphere faster than the waves: the spread forcing's bump stands at most
// kSpreadTopShare of the way up to the sphere's top (shared/sphere_spread.h,
// fastSpreadVariance), fully from kFastFroude times the wave speed on, eased
// in from the wave speed (fastBodyWeight). Below the wave speed the bump is
// the free surface's. docs/water-numerics.md, "Faster than the wave speed".
inline constexpr double kSpreadTopShare = 0.75;
inline constexpr double kFastFroude = 1.5;

// fastSpreadVariance's `fast` for a body moving at `froude` times the wave
// speed: 0 up to 1, 1 from kFastFroude, a smoothstep between.
inline double fastBodyWeight(double froude) {
  const double t = (froude - 1.0) / (kFastFroude - 1.0);
  if (!(t > 0.0)) return 0.0;
  if (t >= 1.0) return 1.0;
  return t * t * (3.0 - 2.0 * t);
}

// A sphere near the wave speed. The wave equation's wake over a body at
// U = F c deepens as the bump's peak times 1 / sqrt(1 - F^2) - 1, without
// bound as F nears 1. That growth is the non-dispersive equation's: water
// whose waves disperse, as real water does, has no such speed. So from
// kWakeFroude on, the spread forcing's bump is widened (its variance times
// wakeWidening, its volume kept) until its peak times that factor stays at
// kWakeFroude's, up to kWakeCapFroude; the widening is then held, and eased
// out above the wave speed as the fast widening comes in.
// docs/water-numerics.md, "The bump widened near the wave speed".
inline constexpr double kWakeFroude = 0.5;
inline constexpr double kWakeCapFroude = 0.95;

// The wave equation's steady deepening of the wake over a round bump's
// centre at `froude` (< 1), in units of the bump's peak.
inline double wakeDeepening(double froude) { return 1.0 / std::sqrt(1.0 - froude * froude) - 1.0; }

// The factor on the spread bump's variance for a body moving at `froude`
// times the wave speed: exactly 1 up to kWakeFroude, then the deepening's
// growth over kWakeFroude's, held from kWakeCapFroude, and eased back to 1
// by kFastFroude as fastBodyWeight rises.
inline double wakeWidening(double froude) {
  if (!(froude > kWakeFroude)) return 1.0;
  const double held = wakeDeepening(kWakeCapFroude) / wakeDeepening(kWakeFroude);
  if (froude < kWakeCapFroude) return wakeDeepening(froude) / wakeDeepening(kWakeFroude);
  return 1.0 + (held - 1.0) * (1.0 - fastBodyWeight(froude));
}

// The 2D bound on the Courant number lambda = c dt / h: the checkerboard mode
// is stable only for lambda <= 1/sqrt(2) (DESIGN.md, "Numerics of the water").
inline constexpr double kStabilityBound = 0.70710678118654752440;

// The slope limiter's share: across an edge steeper than maxSlope, this share
// of the height difference over maxSlope * h flows down in a step. An eighth
// brings a checkerboard (every edge steep, each cell's four and each
// neighbour's four) to the limit in one step without passing it.
inline constexpr double kSlopeShare = 0.125;

struct WaterParams {
  uint32_t n = 256;        // cells per side
  double extent = 2.0;     // L, metres per side; h = L / n
  double waveSpeed = 0.5;  // c, m/s
  double damping = 0.0;    // gamma, 1/s (a rate, so it does not change with dt)
  Boundary boundary = Boundary::Clamp;
  // > 0: the slope limiter. Neighbours whose heights differ by more than
  // maxSlope * h pass kSlopeShare of the excess across their edge each step,
  // which keeps the volume (docs/water-numerics.md).
  double maxSlope = 0.0;
  Scheme scheme = Scheme::Symplectic;
  // kappa, 1/s: v gains kappa h^2 times its discrete Laplacian each second,
  // which damps the shortest waves (the checkerboard's amplitude at 4 kappa) and leaves
  // long ones nearly alone (kappa (h k)^2 / 2). docs/water-numerics.md.
  double gridDamping = 0.0;
  // Clamp boundary: the rim's height over the rest level. A cell along a wall
  // that would rise above it stays at it (its water spills out of the pool).
  double spillHeight = std::numeric_limits<double>::infinity();
  SphereForcing sphereForcing = SphereForcing::Column;
  // The spread forcing's widening per metre of the body's depth: the free
  // surface's (kSpreadDepthFactor) in scenes; `bench wake` varies it to show
  // how the crest answers a wider bump (docs/water-numerics.md).
  double spreadDepthFactor = kSpreadDepthFactor;
  // The spread forcing's bump widened near the wave speed (wakeWidening), as
  // in scenes; `bench wake` turns it off to show the wake without it.
  bool widenNearWaveSpeed = true;
  // The cells the water cannot enter: objects standing through its surface
  // (solidCellsOf, sim/water_scene.hpp). One bit a cell: cell k = j n + i is
  // bit k % 32 of word k / 32. A solid cell keeps its state, and an open
  // neighbour sees its own height and velocity in its place, as at the
  // pool's walls, so no water crosses the edge between. Empty: none.
  std::vector<uint32_t> solid = {};

  double h() const { return extent / n; }
  double lambda(double dt) const { return waveSpeed * dt / h(); }
};

// The words of a solid-cell mask for an n x n grid, and one cell's bit.
inline size_t solidWords(uint32_t n) { return (size_t(n) * n + 31) / 32; }
inline bool isSolid(const std::vector<uint32_t>& solid, size_t k) {
  return !solid.empty() && ((solid[k / 32] >> (k % 32)) & 1u) != 0u;
}
inline void markSolid(std::vector<uint32_t>& solid, size_t k) { solid[k / 32] |= 1u << (k % 32); }

// The solid cells as the step reads them (lib/water_solid.glsl): one byte a
// cell, four a word (cell k is byte k % 4 of word k / 4), 0 for an open
// cell, else the fewest steps between neighbours (under p.boundary) to an
// open one, at most 255. A solid cell's ghost height follows its neighbours
// one nearer the water. All zero where no cell is solid.
std::vector<uint32_t> solidDepths(const WaterParams& p);
inline size_t solidDepthWords(uint32_t n) { return (size_t(n) * n + 3) / 4; }
inline uint32_t solidDepthAt(const std::vector<uint32_t>& depths, size_t k) {
  return (depths[k / 4] >> (k % 4 * 8)) & 255u;
}

// Throws with the name and bound of the first impossible parameter.
void validate(const WaterParams& p);

// The share of an edge's excess the slope limiter moves in a step: 0 when
// it is off.
double slopeShare(const WaterParams& p);

// The bound on lambda = c dt / h: 1/sqrt(2), and with the slope limiter on
// (share s) sqrt(1 - 4 s) times that, 1/2 (docs/water-numerics.md).
double lambdaBound(const WaterParams& p);

// The largest kappa * dt with which a step of dt is stable: the symplectic
// step's amplification matrix has its eigenvalues in the unit disc for every
// mode when 8 d lambda^2 + 16 kappa dt <= 2 + 2 d, d = exp(-gamma dt); with
// the slope limiter, whose steep edges act on the heights as a diffusion of
// share s, when 8 d lambda^2 + (16 - 64 s) kappa dt <= (2 + 2 d)(1 - 4 s)
// (docs/water-numerics.md).
double gridDampingBound(const WaterParams& p, double dt);

// Throws when lambda(dt) exceeds lambdaBound, or kappa * dt exceeds
// gridDampingBound, naming the value and the bound.
void checkStable(const WaterParams& p, double dt);

// The fewest equal substeps of a frame of `frameTime` seconds that keep
// lambda <= safety * lambdaBound and kappa dt <= safety * gridDampingBound.
uint32_t substepsFor(const WaterParams& p, double frameTime, double safety = 0.9);

std::string toString(Boundary b);
std::string toString(Scheme s);
Boundary parseBoundary(const std::string& s);  // throws on anything but clamp|wrap
Scheme parseScheme(const std::string& s);      // throws on anything but symplectic|explicit
std::string toString(SphereForcing f);
SphereForcing parseSphereForcing(const std::string& s);  // throws on anything but column|spread

}  // namespace tp::sim
