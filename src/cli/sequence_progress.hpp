#pragma once
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace tp::app {

// Progress through a range of frames: on a terminal (stderr is a tty) one
// line redrawn in place, a bar with the frame, frames per second and the time
// left; otherwise (a log) one plain line per frame on stdout.
class SequenceProgress {
 public:
  // `toRender`: the frames this run will render (those skipped by --resume not counted).
  SequenceProgress(uint32_t toRender, uint32_t rangeFrames);
  // After a frame was written to `path`.
  void rendered(uint32_t frame, const std::string& path);
  // Ends the bar's line on a terminal.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  uint32_t toRender_, rangeFrames_, done_ = 0;
  Clock::time_point start_ = Clock::now();
  bool terminal_;
};

}  // namespace tp::app
