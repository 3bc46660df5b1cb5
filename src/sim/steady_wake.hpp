#pragma once
// The steady wake of a body moving at a constant speed through the linear
// water on a grid that wraps round: what the stepper settles into once its
// start has died away, solved exactly (docs/water-numerics.md, "The steady
// wake"). The independent answer the GPU's crossing is checked against.
#include <vector>

#include "sim/water_params.hpp"

namespace tp::sim {

// The heights (n x n, row-major, mean 0) the stepper with `p` and steps of
// `dt` settles into around a body moving along +x at `speed` m/s that adds
// `bump` (n x n: the heights its forcing gives where it stands, as
// water_sphere.comp computes them) to the water: each Fourier mode of the
// bump, moved by speed * dt a step, times the step's own transfer for that
// mode. Needs the wrap boundary (the modes of a periodic grid); throws
// std::invalid_argument otherwise, or on a bump of the wrong size.
std::vector<double> steadyWake(const WaterParams& p, double dt, double speed, const std::vector<double>& bump);

}  // namespace tp::sim
