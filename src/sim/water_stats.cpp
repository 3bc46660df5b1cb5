#include "sim/water_stats.hpp"

#include <cstdio>
#include <stdexcept>

namespace tp::sim {

void checkHealth(const WaterStats& s, uint64_t step, double maxHeight) {
  if (s.nonFinite > 0) {
    throw std::runtime_error("simulation blew up at step " + std::to_string(step) + ": " + std::to_string(s.nonFinite) +
                             " non-finite values (is the scheme explicit, or lambda over the bound?)");
  }
  if (s.maxAbsU > maxHeight) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "simulation blew up at step %llu: max |u| = %.3g exceeds %.3g",
                  static_cast<unsigned long long>(step), s.maxAbsU, maxHeight);
    throw std::runtime_error(buffer);
  }
}

std::string describe(const WaterStats& s) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "max|u| %.6g  max|v| %.6g  volume %.9g  energy %.9g  non-finite %llu", s.maxAbsU,
                s.maxAbsV, s.volume, s.energy, static_cast<unsigned long long>(s.nonFinite));
  return buffer;
}

}  // namespace tp::sim
