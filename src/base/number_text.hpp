#pragma once
#include <string>

namespace tp::base {

// The shortest text that reads back as the same float: 0.15, 2, 8192, 1e-06.
// Messages print numbers this way, close to how a user wrote them, where
// std::to_string would print 0.150000 and 8192.000000.
std::string numberText(float value);
std::string numberText(double value);

}  // namespace tp::base
