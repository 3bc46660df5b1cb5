#pragma once
#include <vector>

namespace tp::base {

// The median of timed repeats, the upper of the middle two for an even count
// (NaN for none).
double median(std::vector<double> values);

}  // namespace tp::base
