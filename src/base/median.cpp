#include "base/median.hpp"

#include <algorithm>
#include <cmath>

namespace tp::base {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? std::nan("") : values[values.size() / 2];
}

}  // namespace tp::base
