#include "drop_tests/stability/rare_event_shards.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <thread>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "rft/input_error.h"

namespace touchdown::stability {

namespace fs = std::filesystem;
using sweep::DropRecord;

namespace {

constexpr const char* kBatchTitle = "touchdown rare-event shard batch";
// How often a waiting shard looks for the others' files, and when it first says what it waits for
// (then every kReportEvery): a batch of landings takes seconds to minutes.
constexpr auto kPoll = std::chrono::milliseconds(100);
constexpr double kFirstReportS = 5.0, kReportEvery = 60.0;

// The work limits the landings ran under: a rerun with higher ones runs the failed landings again,
// so a file written under other limits may hold other records.
std::string LimitsLine(const sweep::SweepPlan& plan) {
  return "limits max_drop_evaluations=" + std::to_string(plan.rig.integrator.max_rhs_evaluations) +
         " max_drop_wall_time_s=" + io::FormatNumber(plan.rig.integrator.max_wall_time_s);
}

std::vector<std::string> HeaderLines(const sweep::SweepPlan& plan, const sweep::Shard& shard, int64_t first,
                                     int64_t n) {
  return {kBatchTitle,
          "format_version " + std::to_string(sweep::kResultsDbVersion),
          "plan_digest " + sweep::PlanDigest(plan),
          LimitsLine(plan),
          "shard " + shard.Text(),
          "landings " + std::to_string(first) + " to " + std::to_string(first + n - 1)};
}

// Shard `shard`'s landings among first..first+n-1, ascending.
std::vector<int64_t> ShareOf(const sweep::Shard& shard, int64_t first, int64_t n) {
  std::vector<int64_t> out;
  for (int64_t i = first; i < first + n; ++i)
    if (i % shard.count == shard.index) out.push_back(i);
  return out;
}

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A shard's published batch: its records, or why they are not (yet) the ones wanted.
struct ReadBatch {
  bool present = false;
  std::string other_limits;  // written under other limits: the line, to be waited for
  std::vector<DropRecord> records;
};

ReadBatch ReadBatchFile(const std::string& path, const std::vector<std::string>& expected,
                        const std::vector<int64_t>& share) {
  ReadBatch out;
  std::ifstream in(path, std::ios::binary);
  if (!in) return out;  // not published yet
  out.present = true;
  std::vector<std::string> lines(expected.size());
  for (std::string& line : lines) std::getline(in, line);
  const auto refuse = [&](const std::string& why) { throw MakeInputError(path, "", why + "; use another --out"); };
  if (lines[0] != expected[0] || lines[1] != expected[1])
    refuse("is not a rare-event shard batch of this touchdown version (format " + expected[1] + ")");
  if (lines[2] != expected[2])
    refuse("holds the landings of another study or variant (" + lines[2] + ", this run's " + expected[2] + ")");
  if (lines[4] != expected[4] || lines[5] != expected[5])
    refuse("holds '" + lines[4] + "', '" + lines[5] + "' where '" + expected[4] + "', '" + expected[5] +
           "' belong");
  if (lines[3] != expected[3]) {
    out.other_limits = lines[3];
    return out;
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    out.records = sweep::DeserializeRecords(bytes);
  } catch (const std::exception& e) {
    refuse(std::string("is damaged: ") + e.what());
  }
  bool same = out.records.size() == share.size();
  for (size_t k = 0; same && k < share.size(); ++k) same = out.records[k].index == share[k];
  if (!same) refuse("does not hold the shard's landings " + expected[5].substr(9));
  return out;
}

}  // namespace

std::string RareEventShardDir(const std::string& out_dir, const sweep::Shard& shard) {
  return (fs::path(out_dir) / ("shard_" + std::to_string(shard.index) + "_of_" + std::to_string(shard.count)))
      .string();
}

void RequireOneShardSplit(const std::string& out_dir, const sweep::Shard& shard) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(out_dir, ec)) {
    const std::string name = e.path().filename().string();
    int index = 0, count = 0;
    char tail = 0;
    if (std::sscanf(name.c_str(), "shard_%d_of_%d%c", &index, &count, &tail) != 2 || count == shard.count) continue;
    throw MakeInputError("", "--shard",
                         shard.Text() + ": " + out_dir + " holds " + name + ", a shard of the run split " +
                             std::to_string(count) + " ways; run every shard with --shard I/" +
                             std::to_string(count) + ", or give another --out");
  }
}

void RequireOneShardMethod(const std::string& out_dir, const sweep::Shard& shard, const std::string& method) {
  const fs::path own = fs::path(RareEventShardDir(out_dir, shard)) / "method";
  std::error_code ec;
  fs::create_directories(own.parent_path(), ec);
  if (ec) throw MakeInputError(own.parent_path().string(), "", "cannot create: " + ec.message());
  io::WriteFileAtomically(own.string(), [&](std::ostream& out) { out << method << '\n'; });
  for (int j = 0; j < shard.count; ++j) {
    if (j == shard.index) continue;
    const fs::path other = fs::path(RareEventShardDir(out_dir, {j, shard.count})) / "method";
    std::ifstream in(other);
    std::string theirs;
    if (!in || !std::getline(in, theirs) || theirs == method) continue;
    throw MakeInputError("", "--method",
                         method + ": " + out_dir + " holds shard " + sweep::Shard{j, shard.count}.Text() +
                             " of a --method " + theirs + " run (" + other.string() +
                             "); every shard of one --out runs one method: give this one another --out");
  }
}

RareEventShardBarrier::RareEventShardBarrier(std::string out_dir, std::string pass, std::string run_method,
                                             sweep::Shard shard, const std::atomic<int>* stop, std::ostream* log)
    : out_dir_(std::move(out_dir)), pass_(std::move(pass)), run_method_(std::move(run_method)), shard_(shard),
      stop_(stop), log_(log) {
  RequireOneShardMethod(out_dir_, shard_, run_method_);
}

std::string RareEventShardBarrier::OwnDir() const {
  return (fs::path(RareEventShardDir(out_dir_, shard_)) / pass_).string();
}

std::string RareEventShardBarrier::BatchPath(const sweep::Shard& shard, int64_t first) const {
  return (fs::path(RareEventShardDir(out_dir_, shard)) / pass_ / "batches" / (std::to_string(first) + ".records"))
      .string();
}

std::optional<std::vector<DropRecord>> RareEventShardBarrier::Gather(const sweep::SweepPlan& plan, int64_t first,
                                                                     int64_t n,
                                                                     const std::vector<DropRecord>& own) const {
  const std::string mine = BatchPath(shard_, first);
  std::error_code ec;
  fs::create_directories(fs::path(mine).parent_path(), ec);
  if (ec) throw MakeInputError(fs::path(mine).parent_path().string(), "", "cannot create: " + ec.message());
  // Written again on every run: a rerun under higher limits may have run failed landings again.
  const std::vector<std::string> header = HeaderLines(plan, shard_, first, n);
  io::WriteFileAtomically(mine, [&](std::ostream& out) {
    for (const std::string& line : header) out << line << '\n';
    out << sweep::SerializeRecords(own);
  });
  std::vector<DropRecord> whole(static_cast<size_t>(n));
  for (const DropRecord& r : own) whole[static_cast<size_t>(r.index - first)] = r;
  for (int j = 0; j < shard_.count; ++j) {
    if (j == shard_.index) continue;
    const sweep::Shard other{j, shard_.count};
    const std::string path = BatchPath(other, first);
    const std::vector<int64_t> share = ShareOf(other, first, n);
    const std::vector<std::string> expected = HeaderLines(plan, other, first, n);
    const auto start = std::chrono::steady_clock::now();
    double next_report = kFirstReportS;
    for (;;) {
      ReadBatch b = ReadBatchFile(path, expected, share);
      if (b.present && b.other_limits.empty()) {
        for (DropRecord& r : b.records) whole[static_cast<size_t>(r.index - first)] = std::move(r);
        break;
      }
      if (stop_ && stop_->load() != 0) return std::nullopt;
      RequireOneShardSplit(out_dir_, shard_);
      RequireOneShardMethod(out_dir_, shard_, run_method_);
      if (log_ && Since(start) >= next_report) {
        *log_ << "stability: shard " << shard_.Text() << " waits for shard " << other.Text() << "'s " << pass_
              << " landings " << first << " to " << first + n - 1 << " (" << path << ")"
              << (b.other_limits.empty() ? "" : "; it holds them run under other work limits (" + b.other_limits +
                                                    "): rerun that shard with this one's")
              << "\n"
              << std::flush;
        next_report += kReportEvery;
      }
      std::this_thread::sleep_for(kPoll);
    }
  }
  return whole;
}

}  // namespace touchdown::stability
