#pragma once
// `touchdown sweep`: runs every drop of a SweepPlan into DIR/results.sqlite.
//
// Restartable: drops are committed in batches (one transaction each); a restart with the
// same sweep file skips every stored drop and computes the rest, so a sweep killed at any
// moment (SIGKILL included) and started again ends with exactly the full set, none lost,
// duplicated or half-written. The database records a digest of the plan: resuming with a
// changed sweep file, pad, soil or model is refused rather than mixing results. A restart with
// a higher per-drop limit (max_drop_evaluations, max_drop_wall_time_s) first forgets the drops
// that failed on a lower one, so they are computed again.
//
// Streaming: the plan is never materialised. Drop i's parameters follow from i alone
// (SweepPlan::DropAt), and the drops still to do are found a chunk at a time by range queries
// of the database (RemainingDrops), so a 1e10-drop plan starts in the same memory as a small one.
//
// One writer: the output directory is locked (sweep_lock.h) while a sweep writes it; a second
// sweep or merge on it is refused naming the holder's pid. SIGINT/SIGTERM (sweep_stop.h, through
// SweepRunOptions::stop) end a run cleanly: the drops in flight finish and are committed.
//
// Parallel: threads on one machine (DropEngine), MPI ranks (sweep_mpi.h), or shards
// (`--shard I/N`: drop i belongs to shard i mod N; each shard writes its own directory and
// MergeSweepResults combines them). A drop's record depends only on its index, so results are
// bit-identical for any number of threads, ranks or shards.
#include <atomic>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/util/progress.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep_lock.h"
#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::sweep {

struct Shard {
  int index = 0;
  int count = 1;
  std::string Text() const { return std::to_string(index) + "/" + std::to_string(count); }
};
// Parses "I/N" (0 <= I < N); throws InputError naming `context`.
Shard ParseShard(const std::string& text, const std::string& context = "--shard");

using ProgressMode = io::ProgressMode;

struct SweepRunOptions {
  int threads = 0;  // 0: every core
  Shard shard;
  size_t batch_size = 512;         // drops per transaction, at most
  double commit_interval_s = 0.5;  // and a transaction at least this often while drops finish
  ProgressMode progress = ProgressMode::kAuto;  // auto: a bar on a terminal, else lines
  double progress_interval_s = 10.0;            // for lines
  double progress_quiet_s = 0.0;                // nothing shown before (trade: a quick study prints nothing)
  std::ostream* log = nullptr;                  // progress and failed drops; default std::cerr
  io::ProgressCounts* progress_counts = nullptr;  // the drops done and in all, kept up to date when given
  // When it becomes non-zero (a signal number, StopOnSignals::flag()), the run stops: running
  // drops finish and are committed, the rest is left for a restart. nullptr: never.
  const std::atomic<int>* stop = nullptr;
  // Only these drops of the plan (each in [0, plan size); order and repeats do not matter), the
  // shard's share of them (i mod N == I); the others are neither run nor counted. Absent: every
  // drop. A stability study's follow-ups run the landings they re-run this way.
  std::optional<std::vector<int64_t>> indices;
};

struct SweepRunSummary {
  int64_t total = 0;         // drops in the sweep
  int64_t in_shard = 0;      // drops this run is responsible for (of SweepRunOptions::indices, if given)
  int64_t already_done = 0;  // found in the database at the start
  int64_t computed = 0;      // run now
  int64_t failed = 0;        // failed drops stored (in the shard), old and new
  int64_t retried = 0;       // drops that had failed on a lower limit, forgotten to run again
  int stop_signal = 0;       // the signal that stopped the run early (0: it ran to the end)
  double seconds = 0.0;
  int ranks = 1;
  int threads = 1;
};

// The hex digest of plan.DigestText() that a results database records.
std::string PlanDigest(const SweepPlan& plan);

// A sweep's output directory, locked, with its database open.
struct SweepStore {
  std::unique_ptr<SweepDirLock> lock;
  std::unique_ptr<ResultsDb> db;
  int64_t retried = 0;  // failed drops forgotten because the limits are higher now
};
// Creates DIR, locks it (refusing a directory another process writes), opens DIR/results.sqlite,
// writing the plan's meta on first use and refusing (InputError) a database that holds a
// different sweep or shard; records the run's per-drop limits in the meta and forgets the
// failed drops whose limit was lower than the plan's.
SweepStore OpenSweepStore(const SweepPlan& plan, const std::string& out_dir, const Shard& shard);

// The shard's drops not yet in the database, ascending, a chunk at a time (range queries of the
// primary key), so memory is bounded by the chunk whatever the size of the plan.
class RemainingDrops {
 public:
  RemainingDrops(int64_t total, const ResultsDb& db, const Shard& shard);
  std::vector<int64_t> Next(size_t max);  // empty: none left

 private:
  int64_t total_;
  const ResultsDb& db_;
  Shard shard_;
  int64_t next_;  // the next index of the shard not yet looked at
};

// The drops one run (RunSweep, or rank 0 of RunSweepMpi) is responsible for: the shard's part of
// options.indices when given (ascending, each once), else every drop of the shard; how many that
// is, how many are stored already, and the rest a chunk at a time.
class DropsToRun {
 public:
  DropsToRun(int64_t total, const ResultsDb& db, const SweepRunOptions& options);
  int64_t in_shard() const { return in_shard_; }
  int64_t already_done() const { return already_done_; }
  std::vector<int64_t> Next(size_t max);  // empty: none left

 private:
  RemainingDrops remaining_;
  std::optional<std::vector<int64_t>> listed_todo_;
  size_t listed_fed_ = 0;
  int64_t in_shard_ = 0, already_done_ = 0;
};

SweepRunSummary RunSweep(const SweepPlan& plan, const std::string& out_dir, const SweepRunOptions& options);
// All drops in memory, index order, on `threads` threads (0: every core); no database.
std::vector<DropRecord> RunSweepInMemory(const SweepPlan& plan, int threads);

struct MergeSummary {
  int64_t total = 0, stored = 0, missing = 0, failed = 0;
  int shards = 0;
};
// Combines shard directories into `out_dir` (a fresh or compatible results database). Shards
// must come from the same plan; a drop present in several must be bit-identical.
MergeSummary MergeSweepResults(const std::string& out_dir, const std::vector<std::string>& shard_dirs);

// Progress on a terminal (a bar: done/total, drops/s, ETA) or as plain periodic lines, and
// one line per failed drop; for lander drops also how many of this run's landings tipped over
// (what a stability study watches). Used by RunSweep and the MPI runner.
class SweepProgress {
 public:
  SweepProgress(std::ostream& out, ProgressMode mode, double interval_s, int64_t total, int64_t done_before,
                double quiet_s = 0.0, io::ProgressCounts* counts = nullptr);
  void Add(const std::vector<DropRecord>& records);  // prints failures, updates the display
  void Finish();
  int64_t failed_now() const { return failed_; }

 private:
  std::string Detail() const;
  io::Progress progress_;
  int64_t failed_ = 0;
  int64_t landings_ = 0, tipped_ = 0;  // lander drops of this run
};

}  // namespace touchdown::sweep
