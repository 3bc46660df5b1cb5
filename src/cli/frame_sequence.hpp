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

// Throws a UsageError naming `--frames frames` unless `pattern` holds exactly
// one place for the frame number, in one of the conventions DCCs write:
// "####" (padded to the run's length, "#" unpadded), "%04d" or "%d"
// (printf, ffmpeg, Nuke), "$F4" or "$F" (Houdini).
void checkFramePattern(const std::string& pattern, const std::string& frames);

// `pattern` with its frame number's place replaced by the frame number,
// zero-padded to the place's width ("shot.####.exr", "shot.%04d.exr" and
// "shot.$F4.exr", 7: "shot.0007.exr"); a number longer than the width is
// written whole. A pattern without a place is returned as it is.
std::string framePath(const std::string& pattern, uint32_t frame);

}  // namespace tp::app
