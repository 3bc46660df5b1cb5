#pragma once
#include <cstdint>

#include "sim/water_params.hpp"

namespace tp::sim {

// Exact answers for the clamp-boundary eigenmode u0 = A cos(M pi x/L) cos(N pi z/L)
// with gamma = 0 (DESIGN.md, "Numerics of the water"). The scheme's stored
// velocity is staggered (v between t_{n-1} and t_n), so "at rest" has two
// readings: a stored v = 0 (DESIGN.md's formula, only first-order accurate in
// time because it starts half a step off), or startAtRest()'s v_{-1/2} =
// -(dt/2) c^2 L(u0), after which u_n = u0 cos(n theta), second order.
struct ExactMode {
  WaterParams params;
  int m = 1, nz = 1;
  double amplitude = 1.0;
  double dt = 0.0;

  // sigma = 4 sin^2(M pi h/2L) + 4 sin^2(N pi h/2L): the mode's eigenvalue of
  // minus the grid Laplacian, times h^2 (8 for the checkerboard).
  double sigma() const;
  // theta with sin^2(theta/2) = lambda^2 [sin^2(M pi h/2L) + sin^2(N pi h/2L)].
  double theta() const;
  // u_n / u_0 from a stored v = 0: cos((n + 1/2) theta) / cos(theta / 2).
  double discreteFactorFromZeroVelocity(double step) const;
  // u_n / u_0 after startAtRest(): cos(n theta).
  double discreteFactorAtRest(double step) const;
  // u_n / u_0 after startAtRest() under any damping gamma and grid damping
  // kappa: the step's 2x2 map of the mode's (u, v) applied n times in
  // double. With both 0 it is discreteFactorAtRest().
  double discreteFactorIterated(uint64_t steps) const;
  // The continuous mode's factor at t = step * dt: cos(omega t), omega = c pi sqrt(M^2 + N^2) / L.
  double continuousFactor(double step) const;
};

}  // namespace tp::sim
