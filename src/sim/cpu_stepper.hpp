#pragma once
#include <vector>

#include "shared/water.h"
#include "sim/water_params.hpp"
#include "sim/water_state.hpp"

namespace tp::sim {

// The GPU's step as a well-optimised multithreaded C++ loop (float, the same
// (x, u, z, v) layout, OpenMP over rows, vectorised inner loop): the peer the
// benchmark measures the GPU against. Not a reference: see ReferenceSim.
class CpuStepper {
 public:
  CpuStepper(const WaterParams& params, const WaterState& initial);
  void steps(uint64_t count, double dt);
  WaterState state() const;
  static int threads();

 private:
  WaterParams p_;
  std::vector<shader::WaterCell> a_, b_;
};

// Sets flush-to-zero and denormals-are-zero for this thread (and returns the
// previous state to restore): a decaying wave must not slow a loop down when
// its values fall into the denormal range.
unsigned flushDenormals();
void restoreFloatMode(unsigned previous);

}  // namespace tp::sim
