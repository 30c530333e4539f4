#include "drop_tests/util/work_pool.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <utility>

namespace touchdown::io {

namespace {
// The stop request of the StopScope this thread runs in (nullptr: none).
thread_local const std::atomic<int>* t_stop = nullptr;

void ThrowIfStopped(const std::atomic<int>* stop) {
  if (stop == nullptr) return;
  if (const int signal = stop->load(); signal != 0) throw Stopped(signal);
}
}  // namespace

int EveryCore() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

int ThreadsFor(int requested, int processes_on_node) {
  return requested > 0 ? requested : std::max(1, EveryCore() / std::max(1, processes_on_node));
}

StopScope::StopScope(const std::atomic<int>* stop) : outer_(t_stop) { t_stop = stop; }

StopScope::~StopScope() { t_stop = outer_; }

WorkPool::WorkPool(int threads) {
  for (int i = 0; i < std::max(1, threads); ++i) threads_.emplace_back([this] { Work(); });
}

WorkPool::~WorkPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    shutdown_ = true;
    tasks_.clear();
  }
  work_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void WorkPool::Post(std::function<void()> task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    tasks_.push_back(std::move(task));
  }
  work_.notify_one();
}

size_t WorkPool::Clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  const size_t n = tasks_.size();
  tasks_.clear();
  if (running_ == 0) idle_.notify_all();
  return n;
}

size_t WorkPool::queued() {
  std::lock_guard<std::mutex> lock(mutex_);
  return tasks_.size();
}

void WorkPool::Wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [&] { return tasks_.empty() && running_ == 0; });
}

void WorkPool::Work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    work_.wait(lock, [&] { return shutdown_ || !tasks_.empty(); });
    if (tasks_.empty()) return;  // shutting down
    std::function<void()> task = std::move(tasks_.front());
    tasks_.pop_front();
    ++running_;
    lock.unlock();
    task();  // tasks catch their own exceptions (ParallelFor does)
    lock.lock();
    --running_;
    if (running_ == 0 && tasks_.empty()) idle_.notify_all();
  }
}

void ParallelFor(size_t n, int threads, const std::function<void(size_t)>& body) {
  const size_t workers = std::min(static_cast<size_t>(std::max(1, threads)), n);
  const std::atomic<int>* stop = t_stop;
  if (workers <= 1) {
    for (size_t i = 0; i < n; ++i) {
      ThrowIfStopped(stop);
      body(i);
    }
    return;
  }
  std::atomic<size_t> next{0};
  std::atomic<size_t> lowest_failed{n};
  std::mutex mutex;
  std::exception_ptr error;
  WorkPool pool(static_cast<int>(workers));
  for (size_t w = 0; w < workers; ++w)
    pool.Post([&] {
      const StopScope scope(stop);  // nested loops of the bodies stop alike
      // An index above one that failed is skipped; every index below it still runs.
      for (size_t i = next++; i < n && i < lowest_failed.load(); i = next++) {
        try {
          ThrowIfStopped(stop);
          body(i);
        } catch (...) {
          std::lock_guard<std::mutex> lock(mutex);
          if (i < lowest_failed.load()) lowest_failed = i, error = std::current_exception();
        }
      }
    });
  pool.Wait();
  if (error) std::rethrow_exception(error);
}

}  // namespace touchdown::io
