#include "sim/cpu_stepper.hpp"

#include <omp.h>
#include <xmmintrin.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tp::sim {

unsigned flushDenormals() {
  const unsigned previous = _mm_getcsr();
  _mm_setcsr(previous | 0x8040);  // FTZ (bit 15) and DAZ (bit 6)
  return previous;
}

void restoreFloatMode(unsigned previous) { _mm_setcsr(previous); }

CpuStepper::CpuStepper(const WaterParams& params, const WaterState& initial)
    : p_(params), a_(toCells(initial, params.extent)), b_(a_) {
  p_.n = initial.n;
  // The benchmark's peer steps open water alone: its inner loop has no room for a mask.
  if (!p_.solid.empty()) throw std::runtime_error("the CPU stepper has no solid cells: step this water on the GPU");
}

int CpuStepper::threads() { return omp_get_max_threads(); }

void CpuStepper::steps(uint64_t count, double dt) {
  const int n = int(p_.n);
  const float h = float(p_.h());
  const float waveFactor = float(dt * p_.waveSpeed * p_.waveSpeed / (double(h) * h));
  const float decay = float(std::exp(-p_.damping * dt));
  const float fdt = float(dt);
  const bool wrap = p_.boundary == Boundary::Wrap;
  const bool symplectic = p_.scheme == Scheme::Symplectic;
  const float maxDifference = float(p_.maxSlope * p_.h());
  const float share = float(slopeShare(p_));
  auto excess = [maxDifference](float difference) { return shader::waterSlopeExcess(difference, maxDifference); };
  const float gridDamping = float(p_.gridDamping * dt);
  const float spillHeight = float(p_.spillHeight);
  for (uint64_t s = 0; s < count; ++s) {
    const shader::WaterCell* __restrict src = a_.data();
    shader::WaterCell* __restrict dst = b_.data();
#pragma omp parallel
    {
      const unsigned mode = flushDenormals();
#pragma omp for schedule(static)
      for (int j = 0; j < n; ++j) {
        const int jS = j > 0 ? j - 1 : (wrap ? n - 1 : 0);
        const int jN = j < n - 1 ? j + 1 : (wrap ? 0 : n - 1);
        const shader::WaterCell* row = src + size_t(j) * n;
        const shader::WaterCell* rowS = src + size_t(jS) * n;
        const shader::WaterCell* rowN = src + size_t(jN) * n;
        shader::WaterCell* out = dst + size_t(j) * n;
        const bool wallRow = !wrap && (j == 0 || j == n - 1);
        auto cell = [&](int i, int iW, int iE) {
          const float u = row[i].u, v = row[i].v;
          const float lap = ((row[iW].u - u) + (row[iE].u - u)) + ((rowS[i].u - u) + (rowN[i].u - u));
          const float velocityLap = ((row[iW].v - v) + (row[iE].v - v)) + ((rowS[i].v - v) + (rowN[i].v - v));
          float vNew = decay * (v + waveFactor * lap) + gridDamping * velocityLap;
          float uNew = u + fdt * (symplectic ? vNew : v);
          if (maxDifference > 0.0f) {
            const float moved =
                (excess(u - row[iW].u) + excess(u - row[iE].u)) + (excess(u - rowS[i].u) + excess(u - rowN[i].u));
            uNew = uNew - share * moved;
          }
          if ((wallRow || (!wrap && (i == 0 || i == n - 1))) && uNew > spillHeight) {  // over the rim: spills
            uNew = spillHeight;
            vNew = std::min(vNew, 0.0f);
          }
          out[i] = {row[i].x, uNew, row[i].z, vNew};
        };
        cell(0, wrap ? n - 1 : 0, 1);
#pragma omp simd
        for (int i = 1; i < n - 1; ++i) cell(i, i - 1, i + 1);
        cell(n - 1, n - 2, wrap ? 0 : n - 1);
      }
      restoreFloatMode(mode);
    }
    std::swap(a_, b_);
  }
}

WaterState CpuStepper::state() const { return fromCells(a_, p_.n); }

}  // namespace tp::sim
