#pragma once
#include <cstdint>
#include <string>

namespace tp::app {

// A range of frame numbers, both ends included.
struct FrameRange {
  uint32_t first = 0, last = 0;
  uint32_t count() const { return last - first + 1; }
};

// "A-B" (A <= B) or "N" (the one frame N). Throws one line naming --frames otherwise.
FrameRange parseFrameRange(const std::string& text);

// Whether `pattern` holds a run of '#', the frame number's place.
bool hasFrameField(const std::string& pattern);

// `pattern` with its (last) run of '#' replaced by the frame number,
// zero-padded to the run's length ("shot.####.exr", 7: "shot.0007.exr"); a
// number longer than the run is written whole.
std::string framePath(const std::string& pattern, uint32_t frame);

}  // namespace tp::app
