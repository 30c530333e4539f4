#pragma once
// Runs sweep drops on the thread pool (io::WorkPool) and hands the finished records to one
// consumer thread (the one that writes the database). The consumer feeds drop indices in chunks
// (Feed) as the queue runs low, so memory is bounded by the chunk, never by the plan; each worker
// takes the next index from the queue, so the work spreads evenly whatever each drop costs.
// Results are a pure function of the index, so which thread ran a drop never shows in the result.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "drop_tests/util/work_pool.h"
#include "drop_tests/sweep/sweep_drop.h"

namespace touchdown::sweep {

class DropEngine {
 public:
  // Starts `threads` workers; they wait for indices.
  DropEngine(const SweepModels& models, int threads);
  // With every index given at once (input closed).
  DropEngine(const SweepModels& models, const std::vector<int64_t>& todo, int threads);
  ~DropEngine();  // stops and joins the workers (unfinished drops are simply not reported)
  DropEngine(const DropEngine&) = delete;
  DropEngine& operator=(const DropEngine&) = delete;

  // While the input is open and fewer than `low` indices are queued, queues next()'s chunk; an
  // empty chunk closes the input.
  void Feed(size_t low, const std::function<std::vector<int64_t>()>& next);
  // Stops early: each worker finishes the drop it is running, queued drops are dropped. The
  // records of the finished ones are still handed out by Take.
  void Stop();
  // Waits until `max` records are ready, every drop given is done (input closed or stopped),
  // fewer than `hungry_below` indices are queued while the input is open, `*interrupt` becomes
  // non-zero, or `timeout_s` passes; returns what is ready (at most `max`).
  std::vector<DropRecord> Take(size_t max, double timeout_s, size_t hungry_below = 0,
                               const std::atomic<int>* interrupt = nullptr);
  // True once the input is closed (or the engine stopped) and every started drop has been
  // computed and taken.
  bool Finished();

 private:
  // Queues more drop indices; CloseInput says no more will come.
  void Add(const std::vector<int64_t>& indices);
  void CloseInput();
  // True while the input is open and fewer than `low` indices are queued: time to Add.
  bool Hungry(size_t low);
  void Run(int64_t index);
  bool IdleLocked() const;  // mutex_ held: input over and every started drop computed
  const SweepModels& models_;
  std::mutex mutex_;
  std::condition_variable ready_;  // consumer: records ready, queue low, or done
  bool closed_ = false, stopped_ = false;
  std::vector<DropRecord> done_;
  size_t added_ = 0, dropped_ = 0, computed_ = 0, taken_ = 0;
  size_t take_max_ = 1, hungry_below_ = 0;  // what the waiting Take wants: wake it only then
  io::WorkPool pool_;  // last: destroyed first, so its workers end before what they use
};

// What a run of the engine reports to and asks of its driver (RunEngine).
struct EngineDriver {
  size_t feed_low = 0;                              // refill below this many queued indices
  std::function<std::vector<int64_t>()> next;       // the next chunk of indices; empty: no more
  std::function<void(std::vector<DropRecord>)> commit;  // a batch of finished records
  size_t batch_size = 512;                          // records per commit, at most
  double commit_interval_s = 0.5;                   // and a commit at least this often
  const std::atomic<int>* stop = nullptr;           // non-zero: stop (running drops finish)
};
// Feeds, drains and stops the engine until every drop given is done and committed: the loop of a
// sweep on one machine (sweep.cpp) and of an MPI worker rank (sweep_mpi.cpp).
void RunEngine(DropEngine& engine, const EngineDriver& driver);

}  // namespace touchdown::sweep
