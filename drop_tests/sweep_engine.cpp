#include "drop_tests/sweep_engine.h"

#include <algorithm>
#include <chrono>

namespace touchdown::drop {

namespace {
constexpr size_t kChunk = 8;  // indices a worker claims at once: few atomics, fine balance
}

DropEngine::DropEngine(const SweepModels& models, std::vector<int64_t> todo, int threads)
    : models_(models), todo_(std::move(todo)) {
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(std::max<size_t>(todo_.size(), 1))));
  for (int i = 0; i < n; ++i) workers_.emplace_back([this] { Work(); });
}

DropEngine::~DropEngine() {
  stop_ = true;
  for (std::thread& t : workers_) t.join();
}

void DropEngine::Work() {
  std::vector<DropRecord> local;
  while (!stop_) {
    const size_t begin = next_.fetch_add(kChunk);
    if (begin >= todo_.size()) break;
    const size_t end = std::min(todo_.size(), begin + kChunk);
    local.clear();
    for (size_t i = begin; i < end && !stop_; ++i) local.push_back(SimulateSweepDrop(models_, todo_[i]));
    {
      std::lock_guard<std::mutex> lock(mutex_);
      computed_ += local.size();
      for (DropRecord& r : local) done_.push_back(std::move(r));
    }
    ready_.notify_one();
  }
}

std::vector<DropRecord> DropEngine::Take(size_t max, double timeout_s) {
  std::unique_lock<std::mutex> lock(mutex_);
  ready_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                  [&] { return done_.size() >= max || computed_ == todo_.size(); });
  std::vector<DropRecord> out;
  const size_t n = std::min(max, done_.size());
  out.assign(std::make_move_iterator(done_.begin()), std::make_move_iterator(done_.begin() + n));
  done_.erase(done_.begin(), done_.begin() + n);
  taken_ += n;
  return out;
}

bool DropEngine::Finished() {
  std::lock_guard<std::mutex> lock(mutex_);
  return taken_ == todo_.size();
}

int DefaultThreads(int ranks_on_node) {
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max(1, cores / std::max(1, ranks_on_node));
}

}  // namespace touchdown::drop
