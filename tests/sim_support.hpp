#pragma once
// Shared helpers of the simulation tests.
#include <algorithm>
#include <cmath>
#include <random>

#include "sim/water_state.hpp"

namespace tp::test {

// White noise of the given amplitude around `level`, v = 0, from a fixed seed:
// the hardest field for round-off, every mode up to the checkerboard excited.
inline sim::WaterState randomState(uint32_t n, double level, double amplitude, uint32_t seed) {
  sim::WaterState s = sim::flatState(n, float(level));
  std::mt19937 rng(seed);
  for (float& u : s.u) u = float(level + amplitude * (double(rng()) / double(rng.max()) - 0.5));
  return s;
}

inline double maxAbsDifference(const std::vector<float>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(double(a[k]) - b[k]));
  return worst;
}

inline double volumeOf(const sim::WaterState& s, double h) {
  double sum = 0.0;
  for (float u : s.u) sum += u;
  return sum * h * h;
}

}  // namespace tp::test
