#include "sim/water_state.hpp"

#include <cmath>
#include <stdexcept>

#include "sim/grid_index.hpp"

namespace tp::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

WaterState flatState(uint32_t n, float level) {
  return WaterState{n, std::vector<float>(size_t(n) * n, level), std::vector<float>(size_t(n) * n, 0.0f)};
}

WaterState modeState(uint32_t n, double extent, int m, int nz, double amplitude, double level) {
  WaterState s = flatState(n);
  const double h = extent / n;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h, z = (j + 0.5) * h;
      s.u[size_t(j) * n + i] =
          float(level + amplitude * std::cos(m * kPi * x / extent) * std::cos(nz * kPi * z / extent));
    }
  }
  return s;
}

void addDrop(WaterState& s, double extent, double x, double z, double radius, double amplitude) {
  const double h = extent / s.n;
  for (uint32_t j = 0; j < s.n; ++j) {
    for (uint32_t i = 0; i < s.n; ++i) {
      const double r = std::hypot((i + 0.5) * h - x, (j + 0.5) * h - z);
      if (r < radius) s.u[size_t(j) * s.n + i] += float(amplitude * 0.5 * (1.0 + std::cos(kPi * r / radius)));
    }
  }
}

std::vector<shader::WaterCell> toCells(const WaterState& s, double extent) {
  const double h = extent / s.n;
  std::vector<shader::WaterCell> cells(size_t(s.n) * s.n);
  for (uint32_t j = 0; j < s.n; ++j) {
    for (uint32_t i = 0; i < s.n; ++i) {
      const size_t k = size_t(j) * s.n + i;
      cells[k] = {float((i + 0.5) * h), s.u[k], float((j + 0.5) * h), s.v[k]};
    }
  }
  return cells;
}

WaterState fromCells(std::span<const shader::WaterCell> cells, uint32_t n) {
  WaterState s = flatState(n);
  for (size_t k = 0; k < s.u.size(); ++k) {
    s.u[k] = cells[k].u;
    s.v[k] = cells[k].v;
  }
  return s;
}

void startAtRest(WaterState& s, const WaterParams& params, double dt) {
  const long n = s.n;
  const double factor = -0.5 * dt * params.waveSpeed * params.waveSpeed / (params.h() * params.h());
  auto at = [&](long i, long j) { return double(s.u[cellIndex(i, j, s.n, params.boundary)]); };
  for (long j = 0; j < n; ++j) {
    for (long i = 0; i < n; ++i) {
      const double laplacianH2 = at(i - 1, j) + at(i + 1, j) + at(i, j - 1) + at(i, j + 1) - 4.0 * at(i, j);
      s.v[size_t(j) * n + size_t(i)] = float(factor * laplacianH2);
    }
  }
}

}  // namespace tp::sim
