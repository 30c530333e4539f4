#include "drop_tests/sweep/sweep_engine.h"

#include <algorithm>
#include <chrono>

namespace touchdown::sweep {

DropEngine::DropEngine(const SweepModels& models, int threads) : models_(models) {
  for (int i = 0; i < std::max(1, threads); ++i) workers_.emplace_back([this] { Work(); });
}

DropEngine::DropEngine(const SweepModels& models, const std::vector<int64_t>& todo, int threads)
    : DropEngine(models, std::min<int>(std::max(1, threads), static_cast<int>(std::max<size_t>(todo.size(), 1)))) {
  Add(todo);
  CloseInput();
}

DropEngine::~DropEngine() {
  Stop();
  for (std::thread& t : workers_) t.join();
}

void DropEngine::Add(const std::vector<int64_t>& indices) {
  if (indices.empty()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (closed_ || stopped_) return;
    queue_.insert(queue_.end(), indices.begin(), indices.end());
  }
  work_.notify_all();
}

void DropEngine::CloseInput() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  work_.notify_all();
  ready_.notify_all();
}

void DropEngine::Stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    queue_.clear();
  }
  work_.notify_all();
  ready_.notify_all();
}

size_t DropEngine::queued() {
  std::lock_guard<std::mutex> lock(mutex_);
  return queue_.size();
}

bool DropEngine::Hungry(size_t low) {
  std::lock_guard<std::mutex> lock(mutex_);
  return !closed_ && !stopped_ && queue_.size() < low;
}

bool DropEngine::IdleLocked() const { return (closed_ || stopped_) && queue_.empty() && computed_ == started_; }

void DropEngine::Work() {
  for (;;) {
    int64_t index;
    bool hungry;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      work_.wait(lock, [&] { return stopped_ || closed_ || !queue_.empty(); });
      if (queue_.empty()) return;  // closed or stopped, nothing left
      index = queue_.front();
      queue_.pop_front();
      ++started_;
      hungry = !closed_ && queue_.size() + 1 == hungry_below_;  // just went below: refill
    }
    if (hungry) ready_.notify_all();
    DropRecord record = SimulateSweepDrop(models_, index);
    bool wake;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++computed_;
      done_.push_back(std::move(record));
      wake = done_.size() >= take_max_ || IdleLocked();
    }
    if (wake) ready_.notify_all();
  }
}

std::vector<DropRecord> DropEngine::Take(size_t max, double timeout_s, size_t hungry_below,
                                         const std::atomic<int>* interrupt) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  std::unique_lock<std::mutex> lock(mutex_);
  take_max_ = std::max<size_t>(max, 1);
  hungry_below_ = hungry_below;
  auto ready = [&] {
    return done_.size() >= max || IdleLocked() || (!closed_ && !stopped_ && queue_.size() < hungry_below) ||
           (interrupt && interrupt->load() != 0);
  };
  // In slices: a signal handler cannot notify a condition variable, so `interrupt` is polled.
  while (!ready()) {
    const Clock::time_point now = Clock::now();
    if (now >= deadline) break;
    const Clock::time_point slice = now + std::chrono::milliseconds(50);
    ready_.wait_until(lock, std::min(deadline, slice));
  }
  std::vector<DropRecord> out;
  const size_t n = std::min(max, done_.size());
  out.assign(std::make_move_iterator(done_.begin()), std::make_move_iterator(done_.begin() + n));
  done_.erase(done_.begin(), done_.begin() + n);
  taken_ += n;
  return out;
}

bool DropEngine::Finished() {
  std::lock_guard<std::mutex> lock(mutex_);
  return IdleLocked() && taken_ == computed_;
}

int DefaultThreads(int ranks_on_node) {
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max(1, cores / std::max(1, ranks_on_node));
}

}  // namespace touchdown::sweep
