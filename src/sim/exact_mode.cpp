#include "sim/exact_mode.hpp"

#include <cmath>

namespace tp::sim {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

double ExactMode::theta() const {
  const double lambda = params.lambda(dt), h = params.h(), L = params.extent;
  const double sx = std::sin(m * kPi * h / (2.0 * L)), sz = std::sin(nz * kPi * h / (2.0 * L));
  return 2.0 * std::asin(lambda * std::sqrt(sx * sx + sz * sz));
}

double ExactMode::discreteFactorFromZeroVelocity(double step) const {
  const double th = theta();
  return std::cos((step + 0.5) * th) / std::cos(0.5 * th);
}

double ExactMode::discreteFactorAtRest(double step) const { return std::cos(step * theta()); }

double ExactMode::continuousFactor(double step) const {
  const double omega = params.waveSpeed * kPi * std::sqrt(double(m * m + nz * nz)) / params.extent;
  return std::cos(omega * step * dt);
}

}  // namespace tp::sim
