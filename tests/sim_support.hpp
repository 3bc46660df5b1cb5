#pragma once
// Shared helpers of the simulation tests.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <random>

#include "sim/water_state.hpp"

namespace tp::test {

// The sum of cell(lo, hi) over the squares of an n x n grid `length` metres
// a side, from the corner at the origin.
template <typename Cell>
double sumOverCells(uint32_t n, float length, Cell cell) {
  const float h = length / float(n);
  double sum = 0.0;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      sum += cell(glm::vec2(float(i) * h, float(j) * h), glm::vec2(float(i + 1) * h, float(j + 1) * h));
    }
  }
  return sum;
}

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

// The highest height of the cells along the grid's edge (the pool's walls).
inline double highestAlongTheWalls(const std::vector<float>& u, uint32_t n) {
  double top = -std::numeric_limits<double>::infinity();
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1) top = std::max(top, double(u[size_t(j) * n + i]));
    }
  }
  return top;
}

inline double volumeOf(const sim::WaterState& s, double h) {
  double sum = 0.0;
  for (float u : s.u) sum += u;
  return sum * h * h;
}

}  // namespace tp::test
