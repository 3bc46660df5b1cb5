#include "base/number_text.hpp"

#include <array>
#include <charconv>

namespace tp::base {
namespace {

template <typename T>
std::string shortest(T value) {
  std::array<char, 64> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), result.ptr);
}

}  // namespace

std::string numberText(float value) { return shortest(value); }
std::string numberText(double value) { return shortest(value); }

}  // namespace tp::base
