#include "cli/sequence_progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace tp::app {
namespace {

constexpr int kBarWidth = 30;

// "1:05" for 65 seconds, "1:02:05" past an hour.
std::string clockTime(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

}  // namespace

SequenceProgress::SequenceProgress(uint32_t toRender, uint32_t rangeFrames)
    : toRender_(toRender), rangeFrames_(rangeFrames), terminal_(isatty(fileno(stderr)) != 0) {}

void SequenceProgress::rendered(uint32_t frame, const std::string& path) {
  ++done_;
  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  const double fps = seconds > 0.0 ? done_ / seconds : 0.0;
  const double left = fps > 0.0 ? (toRender_ - done_) / fps : 0.0;
  if (terminal_) {
    const int filled = int(kBarWidth * uint64_t(done_) / std::max(toRender_, 1u));
    std::fprintf(stderr, "\r[%s%s] %u/%u  frame %u  %.2f fps  %s left ", std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(kBarWidth - filled), '.').c_str(), done_, toRender_, frame, fps,
                 clockTime(left).c_str());
    std::fflush(stderr);
  } else {
    std::printf("frame %u (%u of %u to render, %u in the range): wrote %s; %.2f fps, %s left\n", frame, done_,
                toRender_, rangeFrames_, path.c_str(), fps, clockTime(left).c_str());
    std::fflush(stdout);
  }
}

void SequenceProgress::finish() {
  if (terminal_ && done_ > 0) std::fprintf(stderr, "\n");
}

}  // namespace tp::app
