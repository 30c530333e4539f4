#include "drop_tests/util/work_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace touchdown::io {
namespace {

TEST(ParallelForTest, RunsEveryIndexOnceAndStoresResultsByIndex) {
  for (const int threads : {0, 1, 2, 3, 8}) {
    for (const size_t n : {size_t{0}, size_t{1}, size_t{7}, size_t{1000}}) {
      std::vector<std::atomic<int>> runs(n);
      std::vector<size_t> squares(n, 0);
      ParallelFor(n, threads, [&](size_t i) {
        ++runs[i];
        squares[i] = i * i;
      });
      for (size_t i = 0; i < n; ++i) {
        EXPECT_EQ(runs[i].load(), 1) << "index " << i << ", threads " << threads;
        EXPECT_EQ(squares[i], i * i) << "index " << i << ", threads " << threads;
      }
    }
  }
}

TEST(ParallelForTest, UsesSeveralThreads) {
  std::atomic<int> inside{0}, most{0};
  ParallelFor(4, 4, [&](size_t) {
    const int now = ++inside;
    for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
    }
    // Held long enough for the other workers to enter too.
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (most.load() < 2 && std::chrono::steady_clock::now() < until) std::this_thread::yield();
    --inside;
  });
  EXPECT_GE(most.load(), 2);
}

TEST(ParallelForTest, RethrowsTheExceptionOfTheLowestFailingIndex) {
  for (const int threads : {1, 2, 4}) {
    std::vector<std::atomic<int>> runs(100);
    try {
      ParallelFor(100, threads, [&](size_t i) {
        ++runs[i];
        if (i == 37 || i == 38 || i == 90) throw std::runtime_error("index " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception, threads " << threads;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "index 37") << "threads " << threads;
    }
    // Every index below the lowest failure ran, each once; none ran twice.
    for (size_t i = 0; i < runs.size(); ++i) {
      if (i <= 37) {
        EXPECT_EQ(runs[i].load(), 1) << "index " << i;
      }
      EXPECT_LE(runs[i].load(), 1) << "index " << i;
    }
  }
}

TEST(ParallelForTest, AStopInScopeEndsTheLoopsAtTheNextIndexNestedOnesToo) {
  for (const int threads : {1, 3}) {
    std::atomic<int> stop{0};
    std::atomic<int> ran{0};
    const StopScope scope(&stop);
    try {
      ParallelFor(50, threads, [&](size_t i) {
        // Indices after 5 wait for the request: otherwise, on a fast machine, the other threads
        // could finish every index before index 5 makes it, and nothing would be left to stop.
        if (i > 5) {
          while (stop.load() == 0) std::this_thread::yield();
        }
        // The bodies' own loops, on the pool's threads, see the same request.
        ParallelFor(4, 2, [&](size_t) { ++ran; });
        if (i == 5) stop.store(2);
      });
      ADD_FAILURE() << "not stopped, threads " << threads;
    } catch (const Stopped& e) {
      EXPECT_EQ(e.signal(), 2);
    }
    // One thread: indices 0 to 5 ran whole, then none. More: those running then may stop midway.
    if (threads == 1) {
      EXPECT_EQ(ran.load(), 6 * 4);
    }
    EXPECT_GE(ran.load(), 4) << "threads " << threads;
    EXPECT_LT(ran.load(), 50 * 4) << "threads " << threads;
  }
  // Without a scope, nothing stops a loop.
  std::atomic<int> stop{15};
  int ran = 0;
  ParallelFor(10, 1, [&](size_t) { ++ran; });
  EXPECT_EQ(ran, 10);
  {
    const StopScope scope(&stop);
    EXPECT_THROW(ParallelFor(10, 1, [&](size_t) { ++ran; }), Stopped);
  }
  ParallelFor(10, 1, [&](size_t) { ++ran; });  // the scope's end lifts it
  EXPECT_EQ(ran, 20);
}

TEST(WorkPoolTest, RunsPostedTasksAndWaits) {
  WorkPool pool(3);
  std::vector<std::atomic<int>> runs(50);
  for (size_t i = 0; i < runs.size(); ++i) pool.Post([&runs, i] { ++runs[i]; });
  pool.Wait();
  EXPECT_EQ(pool.queued(), 0u);
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "task " << i;
}

TEST(WorkPoolTest, ClearDropsTheTasksNotStarted) {
  WorkPool pool(1);
  std::atomic<bool> release{false};
  std::atomic<int> ran{0};
  pool.Post([&] {
    while (!release.load()) std::this_thread::yield();
    ++ran;
  });
  // The one worker is busy with the first task (or about to take it): the rest wait in the queue.
  for (int i = 0; i < 10; ++i) pool.Post([&] { ++ran; });
  const size_t cleared = pool.Clear();
  release = true;
  pool.Wait();
  EXPECT_GE(cleared, 10u);
  EXPECT_EQ(static_cast<size_t>(ran.load()) + cleared, 11u);
}

// The one default thread count: a positive request as given, 0 (or less) every hardware thread.
TEST(ThreadsForTest, ZeroMeansEveryCore) {
  EXPECT_EQ(EveryCore(), std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  EXPECT_EQ(ThreadsFor(0), EveryCore());
  EXPECT_EQ(ThreadsFor(-1), EveryCore());
  EXPECT_EQ(ThreadsFor(3), 3);
}

}  // namespace
}  // namespace touchdown::io
