#include "cli/frame_sequence.hpp"

#include "cli/usage_error.hpp"
#include "cli/whole_number.hpp"

#include <stdexcept>
#include <string_view>

namespace tp::app {

FrameRange parseFrameRange(const std::string& text) {
  const size_t dash = text.find('-');
  const auto first = wholeNumber<uint32_t>(std::string_view(text).substr(0, dash));
  const auto last = dash == std::string::npos ? first : wholeNumber<uint32_t>(std::string_view(text).substr(dash + 1));
  if (!first || !last || *first > *last) {
    throw UsageError("--frames " + text + ": expected A-B, frame numbers with A <= B (e.g. 0-99), or one frame N");
  }
  return {*first, *last};
}

bool hasFrameField(const std::string& pattern) { return pattern.find('#') != std::string::npos; }

std::string framePath(const std::string& pattern, uint32_t frame) {
  const size_t end = pattern.rfind('#');
  if (end == std::string::npos) return pattern;
  size_t begin = end;
  while (begin > 0 && pattern[begin - 1] == '#') --begin;
  const size_t width = end - begin + 1;
  std::string number = std::to_string(frame);
  if (number.size() < width) number.insert(0, width - number.size(), '0');
  return pattern.substr(0, begin) + number + pattern.substr(end + 1);
}

}  // namespace tp::app
