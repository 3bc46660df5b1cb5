#pragma once
// How smooth a water surface is: the measures of a moving object's wake
// (docs/water-numerics.md, "The wake of a moving sphere").
#include <cstdint>
#include <vector>

#include "sim/water_state.hpp"

namespace tp::sim {

// A disc of the grid (world metres from the grid's corner) whose cells the
// slope and crest leave out: the waterline of a sphere through the surface,
// where the heightfield runs inside the sphere and is never seen.
struct WaterlineDisc {
  double x = 0.0, z = 0.0, radius = 0.0;
};

struct WakeMeasures {
  // Share of the height variance at wavenumbers |k| above half the grid's
  // Nyquist (pi / (2h)), from the state's cosine transform: the basis of the
  // clamp boundary's eigenmodes, so Parseval's sum holds exactly.
  double highShare = 0.0;
  double maxSlope = 0.0;  // steepest difference of neighbours over h, both outside the discs
  double crest = 0.0;     // highest u above `level` outside the discs
  double trough = 0.0;    // deepest u below `level` outside the discs (positive)
};

// The measures of `s` on a grid of side `extent` resting at `level`.
WakeMeasures measureWake(const WaterState& s, double extent, double level, const std::vector<WaterlineDisc>& hidden);

// Volume of the part of a sphere below `level`: the spherical cap's closed
// form. What a sphere inside the grid displaces in all.
double sphereCapVolume(double radius, double centerY, double level);

// Root-mean-square difference of two states of the same domain (u only),
// the finer averaged over 2^k x 2^k blocks down to the coarser's cells: how
// far apart two grids' answers are.
double rmsDifference(const WaterState& coarse, const WaterState& fine);

}  // namespace tp::sim
