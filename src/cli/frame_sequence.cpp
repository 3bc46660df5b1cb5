#include "cli/frame_sequence.hpp"

#include "cli/usage_error.hpp"
#include "cli/whole_number.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace tp::app {
namespace {

// One place for the frame number in a path: where it is, and its padding.
struct FrameField {
  size_t begin = 0, size = 0;
  size_t width = 1;
};

// The decimal digits of `path` from `at`, as a width; 0 digits read as 1.
size_t digitsAt(const std::string& path, size_t at, size_t& end) {
  end = at;
  while (end < path.size() && std::isdigit(static_cast<unsigned char>(path[end]))) ++end;
  // Two digits at most: a wider field is no convention's, and no frame number is that long.
  if (end - at > 2) return 0;
  return std::max<size_t>(1, wholeNumber<size_t>(std::string_view(path).substr(at, end - at)).value_or(1));
}

// The field that starts at `at`, if one does: a run of '#', "%d" or "%0Nd", "$F" or "$FN".
std::optional<FrameField> fieldAt(const std::string& path, size_t at) {
  if (path[at] == '#') {
    size_t end = at;
    while (end < path.size() && path[end] == '#') ++end;
    return FrameField{at, end - at, end - at};
  }
  size_t end = 0;
  if (path.compare(at, 2, "%d") == 0) return FrameField{at, 2, 1};
  if (path.compare(at, 2, "%0") == 0) {
    const size_t width = digitsAt(path, at + 2, end);
    if (width > 0 && end > at + 2 && end < path.size() && path[end] == 'd') return FrameField{at, end + 1 - at, width};
  }
  if (path.compare(at, 2, "$F") == 0) {
    const size_t width = digitsAt(path, at + 2, end);
    // $F followed by a letter is another Houdini variable ($FPS, $FF), not the frame.
    const bool name = end < path.size() && (std::isalpha(static_cast<unsigned char>(path[end])) || path[end] == '_');
    if (width > 0 && !name) return FrameField{at, end - at, width};
  }
  return std::nullopt;
}

std::vector<FrameField> frameFields(const std::string& path) {
  std::vector<FrameField> fields;
  for (size_t at = 0; at < path.size();) {
    const std::optional<FrameField> field = fieldAt(path, at);
    if (!field) {
      ++at;
      continue;
    }
    fields.push_back(*field);
    at = field->begin + field->size;
  }
  return fields;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
  const size_t dash = text.find('-');
  const auto first = wholeNumber<uint32_t>(std::string_view(text).substr(0, dash));
  const auto last = dash == std::string::npos ? first : wholeNumber<uint32_t>(std::string_view(text).substr(dash + 1));
  if (!first || !last || *first > *last) {
    throw UsageError("--frames " + text + ": expected A-B, frame numbers with A <= B (e.g. 0-99), or one frame N");
  }
  return {*first, *last};
}

void checkFramePattern(const std::string& pattern, const std::string& frames) {
  const std::vector<FrameField> fields = frameFields(pattern);
  const std::string output = "--frames " + frames + ": the output " + pattern;
  if (fields.empty()) {
    throw UsageError(output +
                     " needs #### where the frame number goes (or %04d or $F4; # or %d or $F unpadded), e.g. "
                     "frames/shot.####.exr");
  }
  if (fields.size() > 1) {
    throw UsageError(output + " has two places for the frame number, " +
                     pattern.substr(fields[0].begin, fields[0].size) + " and " +
                     pattern.substr(fields[1].begin, fields[1].size) + ": keep one");
  }
}

std::string framePath(const std::string& pattern, uint32_t frame) {
  const std::vector<FrameField> fields = frameFields(pattern);
  if (fields.empty()) return pattern;
  const FrameField& field = fields.back();
  std::string number = std::to_string(frame);
  if (number.size() < field.width) number.insert(0, field.width - number.size(), '0');
  return pattern.substr(0, field.begin) + number + pattern.substr(field.begin + field.size);
}

}  // namespace tp::app
