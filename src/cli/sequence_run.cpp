#include "cli/sequence_run.hpp"

#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "cli/interrupt_guard.hpp"
#include "io/image_io.hpp"

namespace tp::app {

void addResumeOption(CLI::App* cmd, bool& resume, CLI::Option* frames) {
  cmd->add_flag("--resume", resume,
                "With --frames: leave out the frames whose files are already there and whole (a run stopped or "
                "split goes on where it ended)")
      ->needs(frames);
}

std::vector<uint32_t> framesToWrite(FrameRange range, bool resume, const std::function<bool(uint32_t)>& whole,
                                    const char* verb) {
  std::vector<uint32_t> todo;
  for (uint32_t f = range.first;; ++f) {
    if (!(resume && whole(f))) todo.push_back(f);
    if (f == range.last) break;
  }
  if (todo.empty()) {
    std::printf("frames %u-%u: all %u already written\n", range.first, range.last, range.count());
  } else if (todo.size() < range.count()) {
    std::printf("frames %u-%u: %zu already written, %zu to %s\n", range.first, range.last, range.count() - todo.size(),
                todo.size(), verb);
  }
  return todo;
}

bool imageIsWhole(const std::string& path, uint32_t width, uint32_t height) {
  try {
    if (!std::filesystem::is_regular_file(path)) return false;
    const io::FloatImage image = io::readImage(path);
    return image.width == width && image.height == height && image.channels.size() >= 4;
  } catch (const std::exception&) {
    return false;  // truncated or not an image: written again
  }
}

int reportStop(const char* command, uint32_t written, size_t toWrite, const char* verb) {
  const int signal = InterruptGuard::received();
  std::fprintf(stderr,
               "%s: stopped by %s after %u of %zu frames, each written whole; run again with --resume to %s the rest\n",
               command, signal == SIGINT ? "SIGINT" : "SIGTERM", written, toWrite, verb);
  return InterruptGuard::exitCode();
}

}  // namespace tp::app
