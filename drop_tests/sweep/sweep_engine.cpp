#include "drop_tests/sweep/sweep_engine.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <thread>

namespace touchdown::sweep {

DropEngine::DropEngine(const SweepModels& models, int threads) : models_(models), pool_(std::max(1, threads)) {}

DropEngine::DropEngine(const SweepModels& models, const std::vector<int64_t>& todo, int threads)
    : DropEngine(models, std::min<int>(std::max(1, threads), static_cast<int>(std::max<size_t>(todo.size(), 1)))) {
  Add(todo);
  CloseInput();
}

DropEngine::~DropEngine() { Stop(); }

void DropEngine::Add(const std::vector<int64_t>& indices) {
  if (indices.empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (closed_ || stopped_) return;
  added_ += indices.size();
  for (const int64_t index : indices) pool_.Post([this, index] { Run(index); });
}

void DropEngine::CloseInput() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  ready_.notify_all();
}

void DropEngine::Feed(size_t low, const std::function<std::vector<int64_t>()>& next) {
  while (Hungry(low)) {
    const std::vector<int64_t> chunk = next();
    if (chunk.empty()) {
      CloseInput();
      return;
    }
    Add(chunk);
  }
}

void DropEngine::Stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    dropped_ += pool_.Clear();
  }
  ready_.notify_all();
}

bool DropEngine::Hungry(size_t low) {
  std::lock_guard<std::mutex> lock(mutex_);
  return !closed_ && !stopped_ && pool_.queued() < low;
}

bool DropEngine::IdleLocked() const { return (closed_ || stopped_) && computed_ == added_ - dropped_; }

void DropEngine::Run(int64_t index) {
  bool hungry;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    hungry = !closed_ && !stopped_ && pool_.queued() < hungry_below_;  // below the mark: refill
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

std::vector<DropRecord> DropEngine::Take(size_t max, double timeout_s, size_t hungry_below,
                                         const std::atomic<int>* interrupt) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  std::unique_lock<std::mutex> lock(mutex_);
  take_max_ = std::max<size_t>(max, 1);
  hungry_below_ = hungry_below;
  auto ready = [&] {
    return done_.size() >= max || IdleLocked() || (!closed_ && !stopped_ && pool_.queued() < hungry_below) ||
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

void RunEngine(DropEngine& engine, const EngineDriver& d) {
  bool stopping = false;
  auto honour_stop = [&] {
    if (!stopping && d.stop && d.stop->load() != 0) {
      engine.Stop();  // the drops running now finish; nothing new starts
      stopping = true;
    }
  };
  honour_stop();  // a stop asked for before the run starts none (Feed adds nothing once stopped)
  engine.Feed(d.feed_low, d.next);
  while (!engine.Finished()) {
    honour_stop();
    d.commit(engine.Take(d.batch_size, d.commit_interval_s, d.feed_low, stopping ? nullptr : d.stop));
    engine.Feed(d.feed_low, d.next);
  }
}

}  // namespace touchdown::sweep
