#include "stickslip/numerics/parallel_for.hpp"

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace stickslip {
namespace {

TEST(ParallelFor, CallsTheBodyOnceForEveryIndex) {
  for (int threads : {0, 1, 2, 5, 64}) {
    std::vector<std::atomic<int>> calls(37);
    ParallelFor(37, threads, [&](int i) { ++calls[i]; });
    for (int i = 0; i < 37; ++i) EXPECT_EQ(calls[i], 1) << "index " << i << ", " << threads << " threads";
  }
  ParallelFor(0, 4, [](int) { FAIL() << "no item, no call"; });
}

TEST(ParallelFor, RunsOnTheRequestedNumberOfThreads) {
  std::mutex mutex;
  std::set<std::thread::id> seen;
  std::atomic<int> arrived{0};
  // Every item waits until three have started: only three threads can get there (within a
  // deadline, so that a failure shows as a failed expectation rather than a hung test).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  ParallelFor(3, 3, [&](int) {
    {
      const std::lock_guard lock(mutex);
      seen.insert(std::this_thread::get_id());
    }
    ++arrived;
    while (arrived < 3 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
  });
  EXPECT_EQ(seen.size(), 3u);
  EXPECT_EQ(WorkerCount(8, 3), 3);
  EXPECT_EQ(WorkerCount(2, 100), 2);
  EXPECT_GE(WorkerCount(0, 100), 1);
  EXPECT_EQ(WorkerCount(4, 0), 1);
}

TEST(ParallelFor, RethrowsTheFailureOfAnItemAndStartsNoMore) {
  std::atomic<int> started{0};
  EXPECT_THROW(ParallelFor(1000, 1,
                           [&](int i) {
                             ++started;
                             if (i == 10) throw std::runtime_error("item 10");
                           }),
               std::runtime_error);
  EXPECT_EQ(started, 11);
}

}  // namespace
}  // namespace stickslip
