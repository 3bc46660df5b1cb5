#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "shared/water.h"
#include "sim/water_params.hpp"

namespace tp::sim {

// The water state on the host: height u and velocity v, cell (i, j) at
// j * n + i, cell centres at ((i + 1/2) h, (j + 1/2) h).
struct WaterState {
  uint32_t n = 0;
  std::vector<float> u, v;
};

WaterState flatState(uint32_t n, float level = 0.0f);

// u = A cos(M pi x / L) cos(N pi z / L) + level, v = 0: an eigenmode of the
// clamp boundary (DESIGN.md gives its exact discrete evolution).
WaterState modeState(uint32_t n, double extent, int m, int nz, double amplitude, double level = 0.0);

// Adds a raised-cosine bump: amplitude (1 + cos(pi r / radius)) / 2 for r < radius.
void addDrop(WaterState& s, double extent, double x, double z, double radius, double amplitude);

// The stored v is the scheme's staggered velocity (between the previous step
// and this one). A state at rest at t = 0 therefore starts from
// v_{-1/2} = -(dt/2) c^2 L(u): the leapfrog start that keeps the scheme second
// order (a stored v = 0 is half a step off, and only first order).
void startAtRest(WaterState& s, const WaterParams& params, double dt);

// The GPU layout: (x, u, z, v) per cell.
std::vector<shader::WaterCell> toCells(const WaterState& s, double extent);
WaterState fromCells(std::span<const shader::WaterCell> cells, uint32_t n);

}  // namespace tp::sim
