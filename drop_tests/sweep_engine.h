#pragma once
// Runs sweep drops on a pool of threads and hands the finished records to one consumer
// thread (the one that writes the database). Each worker takes the next few indices from a
// shared counter, so the work spreads evenly whatever each drop costs; results are a pure
// function of the index, so which thread ran a drop never shows in the result.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "drop_tests/sweep_drop.h"

namespace touchdown::drop {

class DropEngine {
 public:
  // Starts `threads` workers over `todo` (drop indices).
  DropEngine(const SweepModels& models, std::vector<int64_t> todo, int threads);
  ~DropEngine();  // stops and joins the workers (unfinished drops are simply not reported)
  DropEngine(const DropEngine&) = delete;
  DropEngine& operator=(const DropEngine&) = delete;

  // Waits until `max` records are ready, every drop is done, or `timeout_s` passes, and
  // returns what is ready (at most `max`).
  std::vector<DropRecord> Take(size_t max, double timeout_s);
  // True once every drop has been computed and taken.
  bool Finished();
  size_t total() const { return todo_.size(); }

 private:
  void Work();
  const SweepModels& models_;
  std::vector<int64_t> todo_;
  std::atomic<size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable ready_;
  std::vector<DropRecord> done_;
  size_t computed_ = 0;  // guarded by mutex_
  size_t taken_ = 0;     // consumer side
  std::vector<std::thread> workers_;
};

// Threads to use when the user gives none: every core, shared among the MPI ranks on this node.
int DefaultThreads(int ranks_on_node = 1);

}  // namespace touchdown::drop
