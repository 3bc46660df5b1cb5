#pragma once
#include <cstdint>
#include <string>

namespace tp::sim {

// Health of a water state (DESIGN.md): extremes, volume, energy, and the
// count of non-finite values.
struct WaterStats {
  double maxAbsU = 0.0;
  double maxAbsV = 0.0;
  double volume = 0.0;  // sum of u times h^2 over the cells that hold water (not the solid ones)
  double energy = 0.0;  // the symplectic scheme's conserved energy, times h^2
  uint64_t nonFinite = 0;
};

// Throws "simulation blew up at step S: ..." on a non-finite value or a height
// beyond `maxHeight` (a run that has gone unstable), so garbage is never rendered.
void checkHealth(const WaterStats& stats, uint64_t step, double maxHeight);

std::string describe(const WaterStats& stats);

}  // namespace tp::sim
