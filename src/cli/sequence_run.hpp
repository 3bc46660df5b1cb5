#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cli/frame_sequence.hpp"

namespace tp::app {

// What `render --frames` and `export --frames` share around their frames:
// --resume, and a stop by SIGINT or SIGTERM after the frame being written.

// Adds --resume to a command whose --frames option is `frames`.
void addResumeOption(CLI::App* cmd, bool& resume, CLI::Option* frames);

// The frames of `range` to write: all of them, or with `resume` those for
// which `whole` says the files are not already there whole. Says on stdout
// how many were left out ("frames 0-5: 3 already written, 3 to <verb>").
std::vector<uint32_t> framesToWrite(FrameRange range, bool resume, const std::function<bool(uint32_t)>& whole,
                                    const char* verb);

// Whether the image at `path` is there and whole: readable to its end at
// width x height with at least four channels, as a finished run leaves it.
bool imageIsWhole(const std::string& path, uint32_t width, uint32_t height);

// After a run of `command` (render, export) stopped by a signal: one line on
// stderr saying how many of the frames were written; returns the exit code
// (128 + the signal).
int reportStop(const char* command, uint32_t written, size_t toWrite, const char* verb);

}  // namespace tp::app
