#include "sim/exact_mode.hpp"

#include <cmath>

namespace tp::sim {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

double ExactMode::sigma() const {
  const double h = params.h(), L = params.extent;
  const double sx = std::sin(m * kPi * h / (2.0 * L)), sz = std::sin(nz * kPi * h / (2.0 * L));
  return 4.0 * (sx * sx + sz * sz);
}

double ExactMode::theta() const { return 2.0 * std::asin(params.lambda(dt) * std::sqrt(0.25 * sigma())); }

double ExactMode::discreteFactorFromZeroVelocity(double step) const {
  const double th = theta();
  return std::cos((step + 0.5) * th) / std::cos(0.5 * th);
}

double ExactMode::discreteFactorAtRest(double step) const { return std::cos(step * theta()); }

double ExactMode::discreteFactorIterated(uint64_t steps) const {
  const double h = params.h(), sigma = this->sigma();
  const double c2 = params.waveSpeed * params.waveSpeed;
  const double decay = std::exp(-params.damping * dt), waveFactor = dt * c2 / (h * h);
  const double keep = decay - params.gridDamping * dt * sigma;
  double u = 1.0, v = 0.5 * waveFactor * sigma;  // startAtRest: v = -(dt/2) c^2 L(u)
  for (uint64_t k = 0; k < steps; ++k) {
    v = keep * v - decay * waveFactor * sigma * u;
    u += dt * v;
  }
  return u;
}

double ExactMode::continuousFactor(double step) const {
  const double omega = params.waveSpeed * kPi * std::sqrt(double(m * m + nz * nz)) / params.extent;
  return std::cos(omega * step * dt);
}

}  // namespace tp::sim
