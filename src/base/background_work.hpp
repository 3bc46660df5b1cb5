#pragma once
// Work done on a thread of its own, one job at a time, while the caller goes
// on (render --frames writes frame n while frame n+1 renders). Handing over a
// job waits for the one before it to end, so at most one is in hand: the
// queue is bounded, and jobs run in the order handed over.
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

namespace tp::base {

class BackgroundWork {
 public:
  BackgroundWork();
  // Waits for the job in hand; a failure it had is dropped (call finish()
  // to see it).
  ~BackgroundWork();
  BackgroundWork(const BackgroundWork&) = delete;
  BackgroundWork& operator=(const BackgroundWork&) = delete;

  // Waits for the job before to end, then starts this one. Rethrows the
  // failure of an earlier job instead (this one is then not started).
  void start(std::function<void()> job);
  // Waits for the job in hand to end; rethrows its failure.
  void finish();

 private:
  void waitIdleAndRethrow(std::unique_lock<std::mutex>& lock);
  void run();
  std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> job_;  // empty when idle
  std::exception_ptr failure_;
  bool stopping_ = false;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace tp::base
