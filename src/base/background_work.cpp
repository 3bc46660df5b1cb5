#include "base/background_work.hpp"

namespace tp::base {

BackgroundWork::BackgroundWork() : thread_([this] { run(); }) {}

BackgroundWork::~BackgroundWork() {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !job_; });
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void BackgroundWork::waitIdleAndRethrow(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [this] { return !job_; });
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void BackgroundWork::start(std::function<void()> job) {
  {
    std::unique_lock lock(mutex_);
    waitIdleAndRethrow(lock);
    job_ = std::move(job);
  }
  changed_.notify_all();
}

void BackgroundWork::finish() {
  std::unique_lock lock(mutex_);
  waitIdleAndRethrow(lock);
}

void BackgroundWork::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return job_ || stopping_; });
    if (!job_) return;  // stopping, and nothing in hand
    std::function<void()> job = job_;
    lock.unlock();
    std::exception_ptr failure;
    try {
      job();
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    failure_ = failure;
    job_ = nullptr;
    changed_.notify_all();
  }
}

}  // namespace tp::base
