#include "base/rational.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tp::base {

Rational nearestRational(double value, int32_t maxDenominator) {
  const double largest = double(std::numeric_limits<int32_t>::max());
  if (!(value > 0.0 && value < largest) || maxDenominator < 1) {
    throw std::invalid_argument("nearestRational: " + std::to_string(value) + " is not in (0, 2^31)");
  }
  // Convergents h/k of the continued fraction [a0; a1, a2, ...] of value.
  int64_t h = 1, k = 0, hBefore = 0, kBefore = 1;
  double rest = value;
  for (;;) {
    const double a = std::floor(rest);
    const int64_t hNext = int64_t(a) * h + hBefore, kNext = int64_t(a) * k + kBefore;
    if (kNext > maxDenominator || double(hNext) > largest) break;
    hBefore = h, kBefore = k, h = hNext, k = kNext;
    const double fraction = rest - a;
    // Below this the fraction is the rounding of a value that was a ratio of
    // small integers (1 / (1/30.f) is 30.0000003).
    if (fraction < 1e-6) break;
    rest = 1.0 / fraction;
  }
  return {int32_t(h), int32_t(k)};
}

}  // namespace tp::base
