#pragma once
// The one thread pool of touchdown: the sweep's drop engine (sweep_engine.h), diagnose's gap
// per drop and its fitter's residuals (gap/) all run on it. Work is split by index and every
// result is stored at its index, so which thread ran what never shows in a result.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace touchdown::io {

// A fixed set of threads running queued tasks, in the order queued.
class WorkPool {
 public:
  explicit WorkPool(int threads);  // at least one thread
  ~WorkPool();                     // drops the tasks not started, waits for the running ones
  WorkPool(const WorkPool&) = delete;
  WorkPool& operator=(const WorkPool&) = delete;

  void Post(std::function<void()> task);
  // Removes the tasks not yet started; returns how many.
  size_t Clear();
  // Tasks queued and not yet started.
  size_t queued();
  // Blocks until no task is queued or running.
  void Wait();

 private:
  void Work();
  std::mutex mutex_;
  std::condition_variable work_;  // workers: a task queued, or shutting down
  std::condition_variable idle_;  // Wait: the last task finished
  std::deque<std::function<void()>> tasks_;
  size_t running_ = 0;
  bool shutdown_ = false;
  std::vector<std::thread> threads_;
};

// Runs body(i) once for each i in [0, n) on `threads` threads (1 or fewer: on this thread, in
// order), indices handed out in ascending order; returns when all are done. If a body throws,
// indices not yet started are skipped and the exception of the lowest index that threw is
// rethrown: every index below it has run by then, so which exception comes out does not depend
// on the timing of the threads.
void ParallelFor(size_t n, int threads, const std::function<void(size_t)>& body);

}  // namespace touchdown::io
