#pragma once
// The one thread pool of touchdown: the sweep's drop engine (sweep_engine.h), diagnose's gap
// per drop and its fitter's residuals (gap/) all run on it. Work is split by index and every
// result is stored at its index, so which thread ran what never shows in a result.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace touchdown::io {

// The machine's hardware threads, at least 1 (std::thread::hardware_concurrency may say 0).
int EveryCore();
// The threads a run asking for `requested` uses: `requested` if positive, else every core shared
// among the `processes_on_node` processes on this machine (an MPI sweep's ranks), at least 1: the
// --threads 0 and `threads=0` default of every command and the Python module.
int ThreadsFor(int requested, int processes_on_node = 1);

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
// on the timing of the threads. Within a StopScope, an index not yet started once the stop is
// requested throws Stopped instead of running.
void ParallelFor(size_t n, int threads, const std::function<void(size_t)>& body);

// What ParallelFor throws once a stop was requested: the work is abandoned, not finished.
class Stopped : public std::runtime_error {
 public:
  explicit Stopped(int signal) : std::runtime_error("stopped by signal " + std::to_string(signal)), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

// While alive, every ParallelFor this thread runs, and those its bodies run on the pool's threads,
// check `stop` before each index: once it is non-zero (a signal number) they throw Stopped. A long
// computation made of ParallelFor loops (diagnose's fits, calibrate --targets' evaluations) so
// ends within one body's time of the request, whatever the loops are nested in. Scopes nest; the
// innermost one counts.
class StopScope {
 public:
  explicit StopScope(const std::atomic<int>* stop);
  ~StopScope();
  StopScope(const StopScope&) = delete;
  StopScope& operator=(const StopScope&) = delete;

 private:
  const std::atomic<int>* outer_;
};

}  // namespace touchdown::io
