#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "sim/water_params.hpp"

namespace tp::sim {

// Index of cell (i, j) of an n x n grid, where i and j may step off the grid:
// clamp repeats the edge cell (reflective walls), wrap is periodic.
inline size_t cellIndex(long i, long j, uint32_t n, Boundary boundary) {
  const long side = long(n);
  if (boundary == Boundary::Wrap) {
    i = (i % side + side) % side;
    j = (j % side + side) % side;
  } else {
    i = std::clamp(i, 0L, side - 1);
    j = std::clamp(j, 0L, side - 1);
  }
  return size_t(j) * n + size_t(i);
}

}  // namespace tp::sim
