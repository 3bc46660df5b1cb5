#pragma once
// Checks of numeric options that answer in the user's own words: "--width:
// abc is not a whole number", "--width: 0 is outside 1 to 16384", where
// CLI::Range says "Value abc not in range [1 - 16384]" and prints a float's
// bounds as 2.000000.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include "base/number_text.hpp"
#include "cli/whole_number.hpp"

namespace tp::app {

template <typename T>
std::string boundText(T value) {
  if constexpr (std::is_integral_v<T>) {
    return std::to_string(value);
  } else {
    return base::numberText(value);
  }
}

// A check that the option's text is a number of type T within [lo, hi].
template <typename T>
CLI::Validator inRange(T lo, T hi) {
  const std::string bounds = boundText(lo) + " to " + boundText(hi);
  return CLI::Validator(
      [lo, hi, bounds](std::string& input) -> std::string {
        const std::optional<T> value = wholeNumber<T>(input);
        // A minus sign is out of an unsigned range, not a different kind of text.
        const bool negative =
            std::is_unsigned_v<T> && !input.empty() && input[0] == '-' && wholeNumber<long long>(input).has_value();
        if (!value && !negative) return input + " is not " + (std::is_integral_v<T> ? "a whole number" : "a number");
        if (negative || !(*value >= lo && *value <= hi)) return input + " is outside " + bounds;
        return {};
      },
      bounds);
}

// A check that the option's text is a frame number (0 to 4294967295), a
// negative one answered as such: "-1: a frame number is 0 or more".
inline CLI::Validator frameNumber() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        if (!input.empty() && input[0] == '-' && wholeNumber<long long>(input)) {
          return input + ": a frame number is 0 or more";
        }
        return inRange(0u, std::numeric_limits<uint32_t>::max())(input);
      },
      "0 or more");
}

}  // namespace tp::app
