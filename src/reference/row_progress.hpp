#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>

namespace tp::render {

// Progress of a CPU render whose rows finish on several threads: the callback
// gets the fraction of rows done, at most once per tenth, one call at a time.
class RowProgress {
 public:
  RowProgress(uint32_t rows, std::function<void(double)> report) : rows_(rows), report_(std::move(report)) {}

  void rowDone() {
    const uint32_t done = ++done_;
    if (!report_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (done * 10 / rows_ > reported_) {
      reported_ = done * 10 / rows_;
      report_(double(done) / rows_);
    }
  }

 private:
  uint32_t rows_;
  std::function<void(double)> report_;
  std::atomic<uint32_t> done_{0};
  std::mutex mutex_;
  uint32_t reported_ = 0;
};

}  // namespace tp::render
