#pragma once
// Shards of a rare-event run (`touchdown stability STUDY --method subset|importance --out DIR
// --shard I/N`, a job array on a shared disk). Each batch of the estimator's landings depends on
// the batch before, so the shards run every batch together and meet after it, through files:
//
//   DIR/shard_I_of_N/           shard I's own output, laid out as a single run's DIR: subset/ and
//                               importance/, each with its results.sqlite (meta shard I/N) and
//     <pass>/batches/F.records  the shard's landings of the pass's batch starting at landing F
//                               (those with index mod N == I), published once committed
//
// A shard runs its share of a batch into its database, publishes it (written beside and renamed
// into place: a reader sees the whole file or none), then waits until every other shard's file of
// the batch is there, reads them, and goes on with the whole batch: every shard then picks the same
// next points, and the estimate is bit-identical to a single process's. The shards exchange files,
// not their databases: a SQLite database in WAL mode cannot be read safely while another machine
// writes it, and a renamed file can. Each file names the plan's digest (another study or variant
// in DIR is refused, exit 2), the work limits it ran under (a shard rerun with other limits is
// waited for, not mixed in), the shard and the landings it holds. A shard never writes into
// another's directory. Killed or stopped (SIGINT/SIGTERM while waiting, too), a shard keeps its
// committed landings; the same command resumes it, and publishes its batches again.
#include <atomic>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"

namespace touchdown::stability {

// DIR/shard_I_of_N.
std::string RareEventShardDir(const std::string& out_dir, const sweep::Shard& shard);

// Refuses (InputError naming --shard) a DIR that holds a shard of another split (shard_J_of_M,
// M != N): the shards of one run must agree on N, or each would wait for shards that never come.
void RequireOneShardSplit(const std::string& out_dir, const sweep::Shard& shard);

// Records the run's --method in DIR/shard_I_of_N/method and refuses (InputError naming --method) a
// DIR where another shard's names another: an importance run's shards go on past the subset pass
// that a subset run's shards end with, and would wait for them forever.
void RequireOneShardMethod(const std::string& out_dir, const sweep::Shard& shard, const std::string& method);

// One pass's meeting point of the shards (`pass`: "subset" or "importance") of a run of
// `run_method` (the --method: an importance run has a subset pass too).
class RareEventShardBarrier {
 public:
  // `stop`: when it becomes non-zero, a wait ends (Gather returns nothing). `log`: what a long wait
  // waits for (nullptr: silent).
  RareEventShardBarrier(std::string out_dir, std::string pass, std::string run_method, sweep::Shard shard,
                        const std::atomic<int>* stop, std::ostream* log);
  // This shard's directory of the pass (DIR/shard_I_of_N/<pass>): its sweep output.
  std::string OwnDir() const;
  // Publishes `own` (this shard's landings of first..first+n-1, in index order) and returns the
  // whole batch in index order once every shard has published its share; nothing when stopped
  // while waiting. Throws InputError when a shard's file holds another plan's landings, or DIR a
  // shard of another split.
  std::optional<std::vector<sweep::DropRecord>> Gather(const sweep::SweepPlan& plan, int64_t first, int64_t n,
                                                       const std::vector<sweep::DropRecord>& own) const;

 private:
  std::string BatchPath(const sweep::Shard& shard, int64_t first) const;
  std::string out_dir_, pass_, run_method_;
  sweep::Shard shard_;
  const std::atomic<int>* stop_;
  std::ostream* log_;
};

}  // namespace touchdown::stability
