#pragma once
#include <cstdint>

namespace tp::base {

struct Rational {
  int32_t numerator = 0;
  int32_t denominator = 1;
  bool operator==(const Rational&) const = default;
};

// The continued-fraction convergent of `value` (positive and finite) with the
// largest denominator up to `maxDenominator`: 30/1 for 1 / (1/30.f), 30000/1001
// for NTSC's 29.97. Throws for a value that is not positive and finite.
Rational nearestRational(double value, int32_t maxDenominator);

}  // namespace tp::base
