// base::BackgroundWork, the one-job-at-a-time thread render --frames writes
// its frames on: jobs run in order and never two at once, the caller goes
// on while a job runs, a failure reaches the caller, and nothing handed over
// is lost when it goes away.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <vector>

#include "base/background_work.hpp"

namespace tp::test {
namespace {

TEST(BackgroundWork, RunsJobsInOrderOneAtATime) {
  std::vector<int> order;  // written by the jobs alone, read after finish()
  std::atomic<int> running{0}, mostAtOnce{0};
  base::BackgroundWork work;
  for (int k = 0; k < 50; ++k) {
    work.start([&, k] {
      const int now = ++running;
      mostAtOnce = std::max(mostAtOnce.load(), now);
      order.push_back(k);
      --running;
    });
  }
  work.finish();
  ASSERT_EQ(order.size(), 50u);
  for (int k = 0; k < 50; ++k) EXPECT_EQ(order[size_t(k)], k);
  EXPECT_EQ(mostAtOnce.load(), 1);
}

TEST(BackgroundWork, TheCallerGoesOnWhileAJobRuns) {
  std::promise<void> callerWentOn;
  std::future<void> wentOn = callerWentOn.get_future();
  std::atomic<bool> sawIt{false};
  base::BackgroundWork work;
  // The job ends only once the caller has passed start(): were start() to
  // wait for the job, the job would wait out its (generous) bound instead.
  work.start([&] { sawIt = wentOn.wait_for(std::chrono::seconds(30)) == std::future_status::ready; });
  callerWentOn.set_value();
  work.finish();
  EXPECT_TRUE(sawIt.load());
}

TEST(BackgroundWork, AFailureReachesTheCallerAndStopsTheNextJob) {
  base::BackgroundWork work;
  bool ranAfter = false;
  work.start([] { throw std::runtime_error("disk full"); });
  try {
    work.start([&] { ranAfter = true; });
    work.finish();
    FAIL() << "the failure was not rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "disk full");
  }
  EXPECT_FALSE(ranAfter);
  // Reported once: the work goes on afterwards.
  work.start([&] { ranAfter = true; });
  work.finish();
  EXPECT_TRUE(ranAfter);
}

TEST(BackgroundWork, GoingAwayWaitsForTheJobInHand) {
  std::atomic<bool> done{false};
  {
    base::BackgroundWork work;
    work.start([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      done = true;
    });
  }
  EXPECT_TRUE(done.load());
}

}  // namespace
}  // namespace tp::test
