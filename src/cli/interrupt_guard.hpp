#pragma once

namespace tp::app {

// While alive, SIGINT and SIGTERM do not kill the process: they are noted,
// and long work asks received() between its steps, finishing the step it is
// in (a frame is written whole or not at all) and stopping there. The
// handlers before it are put back when it goes.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal received (SIGINT or SIGTERM), or 0.
  static int received();
  // The exit code for it: 128 + the signal number, as a shell reports a process it killed.
  static int exitCode() { return 128 + received(); }
};

}  // namespace tp::app
