#include "drop_tests/sweep/sweep.h"

#include "drop_tests/formats/output_path.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <unistd.h>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/util/work_pool.h"
#include "drop_tests/sweep/sweep_engine.h"
#include "rft/input_error.h"

namespace touchdown::sweep {

namespace fs = std::filesystem;

namespace {
double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string Hex(uint64_t v) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016" PRIx64, v);
  return buffer;
}

// Drop indices handed to the engine at a time, and the queue length below which it gets more:
// memory bounded by these, never by the plan.
constexpr size_t kFeedChunk = 4096;
constexpr size_t kFeedLow = 1024;

// The listed drops of the shard (SweepRunOptions::indices), ascending, each once; a drop outside
// the plan is a caller's bug.
std::vector<int64_t> ListedDropsOfShard(std::vector<int64_t> listed, int64_t total, const Shard& shard) {
  std::sort(listed.begin(), listed.end());
  listed.erase(std::unique(listed.begin(), listed.end()), listed.end());
  if (!listed.empty() && (listed.front() < 0 || listed.back() >= total))
    throw std::invalid_argument("RunSweep: a listed drop index is outside the plan's " + std::to_string(total));
  std::erase_if(listed, [&](int64_t i) { return i % shard.count != shard.index; });
  return listed;
}

// The listed drops not yet in the database (one range query over the list's span).
std::vector<int64_t> ListedDropsToDo(const std::vector<int64_t>& listed, const ResultsDb& db) {
  if (listed.empty()) return {};
  const std::vector<int64_t> stored = db.StoredIndices(listed.front(), listed.back() + 1);
  std::vector<int64_t> todo;
  std::set_difference(listed.begin(), listed.end(), stored.begin(), stored.end(), std::back_inserter(todo));
  return todo;
}

}  // namespace

std::string PlanDigest(const SweepPlan& plan) { return Hex(Fnv1a64(plan.DigestText())); }

Shard ParseShard(const std::string& text, const std::string& context) {
  Shard s;
  const size_t slash = text.find('/');
  try {
    size_t used_i = 0, used_n = 0;
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    s.index = std::stoi(text.substr(0, slash), &used_i);
    s.count = std::stoi(text.substr(slash + 1), &used_n);
    if (used_i != slash || used_n != text.size() - slash - 1) throw std::invalid_argument("trailing text");
  } catch (const std::exception&) {
    throw MakeInputError("", context, "must be I/N (e.g. 0/4), got '" + text + "'");
  }
  if (s.count < 1 || s.index < 0 || s.index >= s.count)
    throw MakeInputError("", context, "needs 0 <= I < N, got '" + text + "'");
  return s;
}

SweepStore OpenSweepStore(const SweepPlan& plan, const std::string& out_dir, const Shard& shard) {
  io::OpenOutputDirectory(out_dir, io::OutputKind::kSweep);
  SweepStore store;
  store.lock = std::make_unique<SweepDirLock>(out_dir);
  store.db = std::make_unique<ResultsDb>(ResultsDbPath(out_dir));
  ResultsDb& db = *store.db;
  const std::string digest = PlanDigest(plan);
  const std::map<std::string, std::string> meta = db.Meta();
  // The limits of the run, and whether its failed set depends on machine load (only a
  // wall-clock limit makes it so: the evaluation limit fails the same drops everywhere).
  const integ::IntegratorOptions& limits = plan.rig.integrator;
  const std::map<std::string, std::string> limits_meta = {
      {"max_drop_evaluations", std::to_string(limits.max_rhs_evaluations)},
      {"max_drop_wall_time_s", io::FormatNumber(limits.max_wall_time_s)},
      {"load_dependent_failures",
       limits.max_wall_time_s > 0.0 ? "yes: a wall-clock limit per drop (max_drop_wall_time_s) is in use; which "
                                      "drops fail on it depends on machine load"
                                    : "no"}};
  if (meta.empty()) {
    std::map<std::string, std::string> m = {{"format_version", std::to_string(kResultsDbVersion)},
                                            {"sweep_name", plan.name},
                                            {"plan_digest", digest},
                                            {"total_drops", std::to_string(plan.size())},
                                            {"shard", shard.Text()},
                                            {"source", fs::absolute(plan.source).string()},
                                            {"model", plan.model ? fs::absolute(plan.model->source).string() : ""}};
    m.insert(limits_meta.begin(), limits_meta.end());
    // Only when fast (a reference database's meta stays as it was); plan_digest covers it too.
    if (plan.free_drop_model == drop::FreeDropModel::kFast) m["free_drop_model"] = "fast";
    db.SetMeta(m);
    return store;
  }
  auto value = [&](const std::string& key) {
    const auto it = meta.find(key);
    return it == meta.end() ? std::string() : it->second;
  };
  if (value("format_version") != std::to_string(kResultsDbVersion))
    throw MakeInputError(db.path(), "format_version", "written by another touchdown version ('" +
                                                         value("format_version") + "')");
  if (value("plan_digest") != digest)
    throw MakeInputError(db.path(), "plan_digest",
                         "holds results of a different sweep ('" + value("sweep_name") + "' from " + value("source") +
                             "); the sweep file, a pad, a soil or the model changed. Use another --out directory");
  if (value("shard") != shard.Text())
    throw MakeInputError(db.path(), "shard",
                         "holds shard " + value("shard") + ", this run is shard " + shard.Text());
  store.retried = db.ForgetDropsBelowLimits(limits.max_rhs_evaluations, limits.max_wall_time_s);
  db.SetMeta(limits_meta);
  return store;
}

RemainingDrops::RemainingDrops(int64_t total, const ResultsDb& db, const Shard& shard)
    : total_(total), db_(db), shard_(shard), next_(shard.index) {}

std::vector<int64_t> RemainingDrops::Next(size_t max) {
  std::vector<int64_t> out;
  while (out.size() < max && next_ < total_) {
    // A window of the index range holding the next (max - found) drops of the shard.
    const int64_t span = static_cast<int64_t>(max - out.size()) * shard_.count;
    const int64_t end = span < total_ - next_ ? next_ + span : total_;
    const std::vector<int64_t> stored = db_.StoredIndices(next_, end);
    size_t k = 0;
    int64_t i = next_;
    for (; i < end; i += shard_.count) {
      while (k < stored.size() && stored[k] < i) ++k;
      if (k < stored.size() && stored[k] == i) continue;
      out.push_back(i);
    }
    next_ = i;
  }
  return out;
}

SweepProgress::SweepProgress(std::ostream& out, ProgressMode mode, double interval_s, int64_t total,
                             int64_t done_before, double quiet_s, io::ProgressCounts* counts)
    : progress_("sweep", "drops", total, {mode, interval_s, quiet_s, &out, counts}, done_before) {}

std::string SweepProgress::Detail() const {
  std::string s = ", " + std::to_string(failed_) + " failed";
  if (landings_ > 0)
    s += ", " + std::to_string(tipped_) + " of " + std::to_string(landings_) + " landings run now tipped over";
  return s;
}

void SweepProgress::Add(const std::vector<DropRecord>& records) {
  for (const DropRecord& r : records) {
    if (r.ok && r.kind == DropKind::kLander) {
      ++landings_;
      tipped_ += r.tipped_over == 1.0;
    }
    if (r.ok) continue;
    ++failed_;
    progress_.Note("drop " + r.drop_id + " failed: " + r.failure);
  }
  progress_.Add(static_cast<int64_t>(records.size()), Detail());
}

void SweepProgress::Finish() { progress_.Finish(Detail()); }

DropsToRun::DropsToRun(int64_t total, const ResultsDb& db, const SweepRunOptions& options)
    : remaining_(total, db, options.shard) {
  // With a list of drops, only those (and only their part of the shard) are this run's.
  if (options.indices) {
    const std::vector<int64_t> listed = ListedDropsOfShard(*options.indices, total, options.shard);
    listed_todo_ = ListedDropsToDo(listed, db);
    in_shard_ = static_cast<int64_t>(listed.size());
    already_done_ = in_shard_ - static_cast<int64_t>(listed_todo_->size());
  } else {
    in_shard_ = (total - options.shard.index + options.shard.count - 1) / options.shard.count;
    already_done_ = db.CountBelow(total);
  }
}

std::vector<int64_t> DropsToRun::Next(size_t max) {
  if (!listed_todo_) return remaining_.Next(max);
  const size_t n = std::min(max, listed_todo_->size() - listed_fed_);
  std::vector<int64_t> chunk(listed_todo_->begin() + listed_fed_, listed_todo_->begin() + listed_fed_ + n);
  listed_fed_ += n;
  return chunk;
}

SweepRunSummary RunSweep(const SweepPlan& plan, const std::string& out_dir, const SweepRunOptions& options) {
  const double start = Now();
  SweepStore store = OpenSweepStore(plan, out_dir, options.shard);
  ResultsDb& db = *store.db;
  SweepRunSummary summary;
  summary.total = plan.size();
  DropsToRun todo(plan.size(), db, options);
  summary.in_shard = todo.in_shard();
  summary.already_done = todo.already_done();
  summary.retried = store.retried;
  summary.threads = io::ThreadsFor(options.threads);
  SweepProgress progress(options.log ? *options.log : std::cerr, options.progress, options.progress_interval_s,
                         summary.in_shard, summary.already_done, options.progress_quiet_s, options.progress_counts);
  if (summary.already_done < summary.in_shard) {
    const SweepModels models(plan);
    DropEngine engine(models, summary.threads);
    EngineDriver driver;
    driver.feed_low = kFeedLow;
    driver.next = [&] { return todo.Next(kFeedChunk); };
    driver.commit = [&](std::vector<DropRecord> batch) {
      db.Insert(batch);  // one transaction: all of the batch or none of it
      summary.computed += static_cast<int64_t>(batch.size());
      progress.Add(batch);
    };
    driver.batch_size = options.batch_size;
    driver.commit_interval_s = options.commit_interval_s;
    driver.stop = options.stop;
    RunEngine(engine, driver);
  }
  if (options.stop) summary.stop_signal = options.stop->load();
  progress.Finish();
  summary.failed = db.CountFailed();
  summary.seconds = Now() - start;
  return summary;
}

std::vector<DropRecord> RunSweepInMemory(const SweepPlan& plan, int threads) {
  const SweepModels models(plan);
  std::vector<DropRecord> out(static_cast<size_t>(plan.size()));
  io::ParallelFor(out.size(), io::ThreadsFor(threads),
                  [&](size_t i) { out[i] = SimulateSweepDrop(models, static_cast<int64_t>(i)); });
  return out;
}

MergeSummary MergeSweepResults(const std::string& out_dir, const std::vector<std::string>& shard_dirs) {
  if (shard_dirs.empty()) throw MakeInputError("", "merge", "no shard directories given");
  std::map<std::string, std::string> reference;
  std::vector<std::unique_ptr<ResultsDb>> shards;
  // Each shard once: a directory named twice, or two copies of one shard, would count its drops
  // once and hide that another shard is missing from the list.
  std::map<std::string, std::string> dir_of_path, dir_of_shard;
  for (const std::string& dir : shard_dirs) {
    const std::string path = ResultsDbPath(dir);
    if (!fs::is_regular_file(path)) throw MakeInputError(path, "", "no sweep results here");
    if (const auto [it, fresh] = dir_of_path.emplace(fs::weakly_canonical(path).string(), dir); !fresh)
      throw MakeInputError(dir, "", "given twice (as " + it->second + " too): list each shard directory once");
    auto db = std::make_unique<ResultsDb>(path, ResultsDb::Access::kReadOnly);  // a shard may sit on read-only storage
    std::map<std::string, std::string> meta = db->Meta();
    if (meta.empty()) throw MakeInputError(path, "", "not a sweep results database (no meta)");
    if (reference.empty()) reference = meta;
    for (const char* key : {"format_version", "plan_digest", "total_drops"})
      if (meta[key] != reference[key])
        throw MakeInputError(path, key, "differs from " + shard_dirs.front() + " ('" + meta[key] + "' vs '" +
                                            reference[key] + "'): not shards of one sweep");
    if (const auto [it, fresh] = dir_of_shard.emplace(meta["shard"], dir); !fresh && !meta["shard"].empty())
      throw MakeInputError(path, "shard", "holds shard " + meta["shard"] + ", as " + it->second +
                                              " does: two copies of one shard (list each shard once)");
    shards.push_back(std::move(db));
  }
  io::OpenOutputDirectory(io::OutputTarget(out_dir, shard_dirs), io::OutputKind::kSweep);
  const SweepDirLock lock(out_dir);  // a sweep or merge writing there now is refused
  ResultsDb out(ResultsDbPath(out_dir));
  std::map<std::string, std::string> meta = out.Meta();
  if (meta.empty()) {
    std::map<std::string, std::string> m = reference;
    m["shard"] = Shard{}.Text();  // the merged database is the whole sweep; `sweep` can resume it
    out.SetMeta(m);
  } else if (meta["plan_digest"] != reference["plan_digest"]) {
    throw MakeInputError(out.path(), "plan_digest", "holds a different sweep than the shards");
  }
  MergeSummary summary;
  summary.shards = static_cast<int>(shards.size());
  for (const auto& db : shards) {
    std::vector<DropRecord> batch;
    db->ForEach(
        [&](const DropRecord& r) {
          batch.push_back(r);
          if (batch.size() >= 4096) out.Insert(batch), batch.clear();
        },
        /*with_traces=*/true);
    out.Insert(batch);
  }
  summary.total = std::stoll(reference["total_drops"]);
  summary.stored = out.Count();
  summary.failed = out.CountFailed();
  summary.missing = summary.total - summary.stored;
  return summary;
}

}  // namespace touchdown::sweep
