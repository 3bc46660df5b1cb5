#include "cli/interrupt_guard.hpp"

#include <csignal>

namespace tp::app {
namespace {

volatile std::sig_atomic_t gReceived = 0;
struct sigaction gPreviousInt, gPreviousTerm;

extern "C" void noteSignal(int signal) { gReceived = signal; }

}  // namespace

InterruptGuard::InterruptGuard() {
  gReceived = 0;
  struct sigaction action {};
  action.sa_handler = noteSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &gPreviousInt);
  sigaction(SIGTERM, &action, &gPreviousTerm);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &gPreviousInt, nullptr);
  sigaction(SIGTERM, &gPreviousTerm, nullptr);
}

int InterruptGuard::received() { return gReceived; }

}  // namespace tp::app
