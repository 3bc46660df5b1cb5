#pragma once
// Shared helpers of the simulation tests.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
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

// The volume a sphere occupies below the rest level `level`, summed column by
// column over the cell centres of an n x n grid of side `extent` centred on
// the origin: what the sphere displacement moves out of the water.
inline double submergedVolume(uint32_t n, double extent, double level, glm::dvec3 center, double radius) {
  const double h = extent / n, half = 0.5 * extent;
  double volume = 0.0;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h - half, z = (j + 0.5) * h - half;
      const double r2 = radius * radius - (x - center.x) * (x - center.x) - (z - center.z) * (z - center.z);
      if (r2 <= 0.0) continue;
      const double chordHalf = std::sqrt(r2);
      volume += std::max(0.0, std::min(center.y + chordHalf, level) - (center.y - chordHalf)) * h * h;
    }
  }
  return volume;
}

}  // namespace tp::test
