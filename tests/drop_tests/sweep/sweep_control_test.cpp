// Sweeps under control: one writer per output directory (a lock naming its
// holder), a clean stop on SIGINT/SIGTERM (drops in flight committed, exit 130/143, a rerun
// completes the set bit-identical to an uninterrupted run), the deterministic per-drop
// evaluation limit (same failed set at any thread count; the reason names the limit and its
// value; a rerun with a higher limit retries those drops), a plan of 1e10 drops found to do in
// bounded memory, and `export` streaming the database into the same files as the in-memory path.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <malloc.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_export.h"
#include "drop_tests/sweep/sweep_lock.h"
#include "drop_tests/sweep/sweep_stop.h"
#include "rft/input_error.h"
#include "tests/drop_tests/sweep/sweep_test_support.h"
#include "tests/scratch_dir_test.h"
#include "tests/touchdown_process.h"

namespace {

namespace fs = std::filesystem;
namespace testing_process = touchdown::testing_process;
using namespace touchdown::sweep;
using namespace touchdown::sweep::testing_sweep;
using namespace touchdown::dataset;
using namespace touchdown::io;
using touchdown::InputError;

// Free drops of a mesh pad, tilted: tens of ms each, so a run can be stopped mid-way. The
// speeds spread the work: with a low evaluation limit the fastest drops fail and the rest pass.
const char* kSlowSweep = R"(schema_version: 1
type: sweep
name: slow
traces: decimated
trace_max_samples: 8
fixed: {pad: hex, soil: fjs1_lp}
grid:
  tilt_deg: [0, 3]
  impact_speed_m_s: {from: 0.4, to: 1.6, count: 12}
)";

struct Child {
  pid_t pid = -1;
  std::string out_path, err_path;
};

class SweepControl : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  // Starts touchdown with `args` (no shell), its output to files.
  Child Spawn(const std::vector<std::string>& args, const std::string& tag) {
    Child c;
    c.out_path = (dir_ / (tag + ".out")).string();
    c.err_path = (dir_ / (tag + ".err")).string();
    c.pid = testing_process::StartTouchdown(args, "", c.out_path, c.err_path);
    return c;
  }
  static int Wait(const Child& c) {
    int status = 0;
    ::waitpid(c.pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  }
  static int64_t StoredRows(const fs::path& out) {
    if (!fs::exists(ResultsDbPath(out.string()))) return 0;
    try {
      return ResultsDb(ResultsDbPath(out.string())).Count();
    } catch (const std::exception&) {
      return 0;
    }
  }
  // Waits until `out` holds at least `rows` drops (or 120 s pass).
  static void WaitForRows(const fs::path& out, int64_t rows) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (StoredRows(out) < rows && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
};

TEST_F(SweepControl, ASecondSweepOnTheSameDirectoryIsRefusedNamingTheHolder) {
  const std::string file = Write("quick.yaml", kQuickSweep);
  const fs::path out = dir_ / "out";
  OpenOutputDirectory(out.string(), OutputKind::kSweep);  // a sweep output, as a first run leaves it
  {
    // This process holds the lock: a sweep started on the directory is refused naming our pid,
    // in one line, and writes nothing; so is a merge into it, and a second lock in process.
    const SweepDirLock held(out.string());
    const Child sweep = Spawn({"sweep", file, "--out", out.string(), "--progress", "none"}, "sweep");
    EXPECT_EQ(Wait(sweep), 2);
    const std::string err = Slurp(sweep.err_path);
    EXPECT_NE(err.find("pid " + std::to_string(::getpid())), std::string::npos) << err;
    EXPECT_NE(err.find((out / "sweep.lock").string()), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(fs::exists(ResultsDbPath(out.string())));
    RunSweep(LoadSweepPlan(file), (dir_ / "shard").string(), Quiet(2));
    const Child merge = Spawn({"merge", (dir_ / "shard").string(), "--out", out.string()}, "merge");
    EXPECT_EQ(Wait(merge), 2);
    EXPECT_NE(Slurp(merge.err_path).find("pid " + std::to_string(::getpid())), std::string::npos)
        << Slurp(merge.err_path);
    EXPECT_THROW(RunSweep(LoadSweepPlan(file), out.string(), Quiet(1)), InputError);
    EXPECT_THROW(SweepDirLock again(out.string()), InputError);
  }
  // Two sweep processes: the second is refused naming the first, which keeps running.
  std::string many = kQuickSweep;
  many.replace(many.find("samples: 20"), 11, "samples: 2000");  // 120,000 drops: still running when checked
  const std::string many_file = Write("many.yaml", many);
  const Child first = Spawn({"sweep", many_file, "--out", out.string(), "--threads", "1", "--batch", "8",
                             "--progress", "none"},
                            "first");
  WaitForRows(out, 1);
  const Child second = Spawn({"sweep", many_file, "--out", out.string(), "--progress", "none"}, "second");
  const int second_status = Wait(second);
  const std::string second_err = Slurp(second.err_path);
  EXPECT_EQ(::waitpid(first.pid, nullptr, WNOHANG), 0) << "the first sweep ended early";
  ::kill(first.pid, SIGKILL);
  Wait(first);
  EXPECT_EQ(second_status, 2) << second_err;
  EXPECT_NE(second_err.find("pid " + std::to_string(first.pid)), std::string::npos) << second_err;
  // The holder was killed: its lock went with it.
  EXPECT_NO_THROW(SweepDirLock after(out.string()));
}

TEST_F(SweepControl, SigtermCommitsTheDropsInFlightExits143AndARerunCompletesIdentically) {
  const std::string file = Write("slow.yaml", kSlowSweep);
  const fs::path out = dir_ / "stopped";
  const int64_t total = LoadSweepPlan(file).size();
  for (const int signal : {SIGTERM, SIGINT}) {
    const Child c = Spawn({"sweep", file, "--out", out.string(), "--threads", "2", "--batch", "1", "--progress",
                           "none"},
                          "run");
    const int64_t before = StoredRows(out);
    WaitForRows(out, before + 2);
    ASSERT_EQ(::kill(c.pid, signal), 0);
    const int status = Wait(c);
    const std::string text = Slurp(c.out_path);
    ASSERT_EQ(status, 128 + signal) << text << Slurp(c.err_path);
    EXPECT_NE(text.find(signal == SIGTERM ? "stopped by SIGTERM" : "stopped by SIGINT"), std::string::npos) << text;
    EXPECT_NE(text.find("Run the same command again to resume"), std::string::npos) << text;
    const int64_t stored = StoredRows(out);
    EXPECT_NE(text.find(std::to_string(stored) + " of " + std::to_string(total) + " drops done"), std::string::npos)
        << text;
    EXPECT_GT(stored, before);
    EXPECT_LT(stored, total) << "the sweep finished before it could be stopped";
  }
  // The database is consistent (SQLite's own check) and every stored drop is whole.
  {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open_v2(ResultsDbPath(out.string()).c_str(), &raw, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    sqlite3_stmt* st = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(raw, "PRAGMA integrity_check", -1, &st, nullptr), SQLITE_OK);
    ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
    EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(st, 0)), "ok");
    sqlite3_finalize(st);
    sqlite3_close(raw);
  }
  {
    const ResultsDb db(ResultsDbPath(out.string()));
    for (const DropRecord& r : db.ReadAll(true)) EXPECT_TRUE(r.ok ? !r.trace.empty() : r.trace.empty()) << r.drop_id;
  }
  const Child rerun = Spawn({"sweep", file, "--out", out.string(), "--progress", "none"}, "rerun");
  ASSERT_EQ(Wait(rerun), 0) << Slurp(rerun.err_path);
  RunSweep(LoadSweepPlan(file), (dir_ / "clean").string(), Quiet(2));
  ExpectSameRecords(Records(out), Records(dir_ / "clean"));
}

TEST_F(SweepControl, TheStopFlagEndsARunAfterTheDropsInFlight) {
  const SweepPlan plan = LoadSweepPlan(Write("quick.yaml", kQuickSweep));
  std::atomic<int> stop{SIGTERM};  // set before the first drop: nothing new starts
  SweepRunOptions o = Quiet(2);
  o.stop = &stop;
  const SweepRunSummary s = RunSweep(plan, (dir_ / "out").string(), o);
  EXPECT_EQ(s.stop_signal, SIGTERM);
  EXPECT_EQ(s.computed, 0);  // the flag was up before the first drop: none starts
  EXPECT_EQ(StoredRows(dir_ / "out"), s.computed);
  // StopOnSignals: a raised SIGTERM only sets the flag (and the handler is restored afterwards).
  {
    const StopOnSignals guard;
    EXPECT_EQ(StopOnSignals::flag().load(), 0);
    std::raise(SIGTERM);
    EXPECT_EQ(StopOnSignals::flag().load(), SIGTERM);
  }
  struct sigaction now {};
  sigaction(SIGTERM, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
}

TEST_F(SweepControl, TheEvaluationLimitFailsTheSameDropsAtAnyThreadCountNamingTheLimit) {
  SweepPlan plan = LoadSweepPlan(Write("slow.yaml", kSlowSweep));
  EXPECT_EQ(plan.rig.integrator.max_rhs_evaluations, kDefaultMaxDropEvaluations);
  EXPECT_EQ(plan.rig.integrator.max_wall_time_s, 0.0);
  // The limit decides whether a drop finishes, never what it computes: not in the digest.
  const std::string digest = plan.DigestText();
  plan.rig.integrator.max_rhs_evaluations = 150;
  EXPECT_EQ(plan.DigestText(), digest);
  const std::vector<DropRecord> one = RunSweepInMemory(plan, 1), two = RunSweepInMemory(plan, 2);
  ExpectSameRecords(one, two);
  int failed = 0;
  for (const DropRecord& r : one) {
    if (r.ok) continue;
    ++failed;
    EXPECT_EQ(r.failure_limit, "max_rhs_evaluations") << r.failure;
    EXPECT_EQ(r.failure_limit_value, 150.0);
    EXPECT_NE(r.failure.find("more than 150 right-hand-side evaluations"), std::string::npos) << r.failure;
  }
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, static_cast<int>(one.size()));  // the limit separates cheap drops from costly ones
  // Refused values in the file and on the command line.
  const std::string body = "schema_version: 1\ntype: sweep\nfixed: {pad: flat, soil: fjs1_lp}\n"
                           "grid: {impact_speed_m_s: [0.7, 1.5]}\n";
  EXPECT_EQ(LoadSweepPlan(Write("none.yaml", "max_drop_evaluations: 0\n" + body)).rig.integrator.max_rhs_evaluations,
            0);
  for (const char* bad : {"-1", "2.5", "1e300", "x"})
    EXPECT_THROW(LoadSweepPlan(Write("bad.yaml", std::string("max_drop_evaluations: ") + bad + "\n" + body)),
                 InputError)
        << bad;
}

TEST_F(SweepControl, ARerunWithAHigherLimitRetriesTheDropsThatRanOutOfTheLowerOne) {
  const std::string file = Write("slow.yaml", kSlowSweep);
  const fs::path out = dir_ / "out";
  auto run = [&](const std::vector<std::string>& limit) {
    std::vector<std::string> args = {"sweep", file, "--out", out.string(), "--progress", "none"};
    args.insert(args.end(), limit.begin(), limit.end());
    const Child c = Spawn(args, "run");
    const int status = Wait(c);
    EXPECT_EQ(status, 0) << Slurp(c.err_path);
    return Slurp(c.out_path);
  };
  run({"--max-drop-evaluations", "150"});
  const std::vector<DropRecord> low = Records(out);
  int64_t low_failed = 0;
  for (const DropRecord& r : low) low_failed += !r.ok;
  ASSERT_GT(low_failed, 0);
  EXPECT_EQ(ResultsDb(ResultsDbPath(out.string())).Meta().at("max_drop_evaluations"), "150");
  EXPECT_EQ(ResultsDb(ResultsDbPath(out.string())).Meta().at("load_dependent_failures"), "no");
  // The same or a lower limit: nothing is retried.
  std::string text = run({"--max-drop-evaluations", "120"});
  EXPECT_NE(text.find(", 0 run now"), std::string::npos) << text;
  // A higher one (the default): exactly the drops that ran out are computed again, and the
  // database equals a run with the default limit from the start.
  text = run({});
  EXPECT_NE(text.find(std::to_string(low_failed) + " drops that had failed on a lower limit run again"),
            std::string::npos)
      << text;
  RunSweep(LoadSweepPlan(file), (dir_ / "clean").string(), Quiet(2));
  ExpectSameRecords(Records(out), Records(dir_ / "clean"));
  for (const DropRecord& r : Records(out)) EXPECT_TRUE(r.ok) << r.drop_id << ": " << r.failure;
}

TEST_F(SweepControl, RemainingDropsOfA1e10DropPlanComeInBoundedMemory) {
  // 100000 x 100000 = 1e10 drops (inside the 2^40 cap); planning and finding the first drops to
  // do allocate a few hundred kB, not the 80 GB a list of every index would take.
  const SweepPlan plan = LoadSweepPlan(Write("huge.yaml", R"(schema_version: 1
type: sweep
traces: none
fixed: {pad: flat, soil: fjs1_lp}
grid:
  impact_speed_m_s: {from: 0.3, to: 2.0, count: 100000}
  pad_mass_kg: {from: 1.0, to: 2.0, count: 100000}
)"));
  ASSERT_EQ(plan.size(), int64_t{10000000000});
  const SweepStore store = OpenSweepStore(plan, (dir_ / "out").string(), Shard{});
  // A few stored drops, to be skipped.
  std::vector<DropRecord> stored;
  for (int64_t i : {int64_t{0}, int64_t{2}, int64_t{5000}}) {
    DropRecord r;
    r.index = i;
    r.drop_id = plan.DropId(i);
    r.failure = "test";
    stored.push_back(r);
  }
  store.db->Insert(stored);
  const size_t heap_before = mallinfo2().uordblks;
  RemainingDrops todo(plan.size(), *store.db, Shard{});
  size_t peak = 0;
  int64_t seen = 0, last = -1;
  for (int chunk = 0; chunk < 8; ++chunk) {
    const std::vector<int64_t> next = todo.Next(4096);
    peak = std::max(peak, mallinfo2().uordblks);
    ASSERT_EQ(next.size(), 4096u);
    for (int64_t i : next) {
      EXPECT_GT(i, last);
      EXPECT_TRUE(i != 0 && i != 2 && i != 5000) << i;
      last = i;
    }
    seen += static_cast<int64_t>(next.size());
  }
  EXPECT_EQ(last, seen + 2);  // three skipped
  EXPECT_LT(peak - std::min(peak, heap_before), size_t{4} << 20);
  EXPECT_EQ(store.db->CountBelow(plan.size()), 3);
}

TEST_F(SweepControl, ExportStreamsTheSameFilesAsTheInMemoryDataset) {
  const std::string file = Write("slow.yaml", kSlowSweep);
  const fs::path out = dir_ / "out";
  SweepPlan plan = LoadSweepPlan(file);
  RunSweep(plan, out.string(), Quiet(2));
  for (const bool full : {false, true}) {
    ExportOptions options;
    options.full_traces = full;
    const fs::path streamed = dir_ / (full ? "streamed_full" : "streamed");
    const fs::path memory = dir_ / (full ? "memory_full" : "memory");
    const ExportSummary s = ExportSweep(out.string(), streamed.string(), options);
    EXPECT_EQ(s.exported, plan.size());
    EXPECT_EQ(s.resimulated, full ? plan.size() : 0);
    WriteDataset(SweepToDataset(out.string(), options), memory.string());
    EXPECT_EQ(Slurp(streamed / "drops.csv"), Slurp(memory / "drops.csv"));
    size_t traces = 0;
    for (const auto& entry : fs::directory_iterator(memory / "traces")) {
      EXPECT_EQ(Slurp(streamed / "traces" / entry.path().filename()), Slurp(entry.path())) << entry.path();
      ++traces;
    }
    EXPECT_EQ(traces, static_cast<size_t>(plan.size()));
  }
}

}  // namespace
