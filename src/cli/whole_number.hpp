#pragma once
#include <charconv>
#include <optional>
#include <string_view>

namespace tp::app {

// The whole of `text` as a number of type T, or nothing (empty text, a sign
// an unsigned type does not take, trailing characters, out of range).
template <typename T>
std::optional<T> wholeNumber(std::string_view text) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace tp::app
