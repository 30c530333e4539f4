// Sweeps: the plan (grids, seeded random samples), the restartable SQLite store, and results
// that are bit-identical for 1 or N threads, shards + merge, MPI ranks and a run killed with
// SIGKILL and restarted. The touchdown binary is run as a user would (fork/exec).
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_export.h"
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
using namespace touchdown::pad;
using touchdown::InputError;

// 2 pads x 4 speeds x 2 zetas x 5 random samples = 80 drops; zeta 1e-6 N/cm^3 cannot stop a
// pad within the rig's 10 s, so the 40 drops with it fail and must be recorded as failed.
const char* kSmallSweep = R"(schema_version: 1
type: sweep
name: small
traces: decimated
trace_max_samples: 16
fixed: {soil: fjs1_lp}
grid:
  pad: [flat, curved]
  impact_speed_m_s: {from: 0.5, to: 2.0, count: 4}
  zeta_N_cm3: [0.000001, 3.5]
random: {samples: 5, seed: 11, pad_mass_kg: {uniform: [1.0, 2.5]}, gravity_m_s2: {choice: [1.62, 9.81]}}
)";

struct CliResult {
  int status = -1;
  std::string out, err;
};

class Sweep : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  // Runs a shell command line (the touchdown binary or mpirun) and captures its output.
  CliResult Shell(const std::string& command_line) {
    const std::string out = (dir_ / "stdout").string(), err = (dir_ / "stderr").string();
    const int raw = std::system((command_line + " >" + out + " 2>" + err).c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, Slurp(out), Slurp(err)};
  }
  CliResult Touchdown(const std::string& args) { return Shell(std::string(TOUCHDOWN_BINARY) + " " + args); }

  // Starts touchdown with `args` (no shell) and returns its pid.
  pid_t Spawn(const std::vector<std::string>& args) { return testing_process::StartTouchdown(args); }

  // Rows in DIR/results.sqlite, read-only (0 while the file or table does not exist yet).
  static int64_t StoredRows(const fs::path& out_dir) {
    sqlite3* db = nullptr;
    int64_t n = 0;
    if (sqlite3_open_v2(ResultsDbPath(out_dir.string()).c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
      sqlite3_stmt* st = nullptr;
      if (sqlite3_prepare_v2(db, "SELECT COUNT(*) FROM drops", -1, &st, nullptr) == SQLITE_OK &&
          sqlite3_step(st) == SQLITE_ROW)
        n = sqlite3_column_int64(st, 0);
      sqlite3_finalize(st);
    }
    sqlite3_close(db);
    return n;
  }
};

TEST_F(Sweep, PlanIsTheCartesianProductTimesTheSamples) {
  const SweepPlan plan = LoadSweepPlan(Write("s.yaml", kSmallSweep));
  EXPECT_EQ(plan.size(), 2 * 4 * 2 * 5);
  ASSERT_EQ(plan.pads.size(), 2u);
  // The last-listed grid axis varies fastest, after the random sample.
  const SweepDropParams d0 = plan.DropAt(0), d5 = plan.DropAt(5), d10 = plan.DropAt(10);
  EXPECT_EQ(d0.pad, 0);
  EXPECT_DOUBLE_EQ(d0.impact_speed_m_s, 0.5);
  EXPECT_DOUBLE_EQ(*d0.zeta_N_m3, 1.0);
  EXPECT_DOUBLE_EQ(*d5.zeta_N_m3, 3.5e6);
  EXPECT_DOUBLE_EQ(d10.impact_speed_m_s, 1.0);
  EXPECT_EQ(plan.DropAt(40).pad, 1);
  EXPECT_DOUBLE_EQ(plan.DropAt(79).impact_speed_m_s, 2.0);
  // Random sample s draws the same values at every grid point, within the given bounds.
  for (int s = 0; s < 5; ++s) {
    EXPECT_EQ(*plan.DropAt(s).mass_kg, *plan.DropAt(40 + s).mass_kg);
    EXPECT_GE(*plan.DropAt(s).mass_kg, 1.0);
    EXPECT_LT(*plan.DropAt(s).mass_kg, 2.5);
    const double g = plan.DropAt(s).gravity_m_s2;
    EXPECT_TRUE(g == 1.62 || g == 9.81) << g;
  }
  EXPECT_NE(*plan.DropAt(0).mass_kg, *plan.DropAt(1).mass_kg);
  // Reproducible: a fresh load gives the same drops; another seed other ones.
  const SweepPlan again = LoadSweepPlan((dir_ / "s.yaml").string());
  EXPECT_EQ(*again.DropAt(3).mass_kg, *plan.DropAt(3).mass_kg);
  std::string other = kSmallSweep;
  other.replace(other.find("seed: 11"), 8, "seed: 12");
  EXPECT_NE(*LoadSweepPlan(Write("o.yaml", other)).DropAt(3).mass_kg, *plan.DropAt(3).mass_kg);
  EXPECT_EQ(plan.DropId(7), "d07");
}

TEST_F(Sweep, CounterUniformIsUniformEnough) {
  // Mean and variance of 20000 draws against U(0,1): 1/2 and 1/12, within 4 standard errors.
  const int n = 20000;
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = CounterUniform(7, static_cast<uint64_t>(i), 3);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum_sq += u * u;
  }
  EXPECT_NEAR(sum / n, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(sum_sq / n - (sum / n) * (sum / n), 1.0 / 12.0, 4.0 * 0.0745 / std::sqrt(n));
}

struct BadSweep {
  const char* name;
  std::string text;
  std::string expected;
};
void PrintTo(const BadSweep& c, std::ostream* os) { *os << c.name; }  // readable test names

class SweepBadFile : public Sweep, public ::testing::WithParamInterface<BadSweep> {};

TEST_P(SweepBadFile, RefusedNamingFileAndField) {
  const std::string path = Write("bad.yaml", "schema_version: 1\ntype: sweep\n" + GetParam().text);
  try {
    LoadSweepPlan(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": " + GetParam().expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SweepBadFile,
    ::testing::Values(
        BadSweep{"TiltOutOfRange", "fixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1, tilt_deg: 95}\n",
                 "fixed.tilt_deg: must be strictly between -90 and 90"},
        BadSweep{"RollNeedsALander", "fixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1}\ngrid: {roll_deg: [0, 2]}\n",
                 "grid.roll_deg: a lander parameter"},
        BadSweep{"LanderBlockFields", "lander: {legs: 4}\n", "lander.legs: unknown field"},
        BadSweep{"LanderUnknownScenario", "lander: {scenario: no_such_case}\n", "lander.scenario: "},
        BadSweep{"LanderPadMustFit", "lander: {scenario: lander_case_A}\ngrid: {pad: [flat, c4]}\n",
                 "pad: pad flat does not fit lander sutoh2017_lander (its total_mass_kg: must exceed the four pads' mass; "
                 "pad file "},
        BadSweep{"LanderTakesNoPadMass", "lander: {scenario: lander_case_A}\nfixed: {pad_mass_kg: 1}\n",
                 "fixed.pad_mass_kg: a single-pad parameter"},
        BadSweep{"LanderStoresNoTraces", "lander: {scenario: lander_case_A}\ntraces: full\n",
                 "traces: a lander sweep stores summaries only"},
        BadSweep{"TwiceSet", "fixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1}\ngrid: {pad: [flat, c4]}\n",
                 "grid.pad: set in more than one of fixed, grid and random"},
        BadSweep{"UnknownParameter", "fixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1, speed: 2}\n",
                 "fixed.speed: unknown parameter"},
        BadSweep{"MissingSeed", "fixed: {pad: flat, soil: fjs1_lp}\nrandom: {samples: 3, impact_speed_m_s: {uniform: [0.5, 1]}}\n",
                 "random.seed: missing"},
        BadSweep{"ReversedUniform",
                 "fixed: {pad: flat, soil: fjs1_lp}\nrandom: {samples: 3, seed: 1, impact_speed_m_s: {uniform: [2, 1]}}\n",
                 "random.impact_speed_m_s.uniform: needs low < high"},
        BadSweep{"NegativeSpeed", "fixed: {pad: flat, soil: fjs1_lp}\ngrid: {impact_speed_m_s: [1, -1]}\n",
                 "grid.impact_speed_m_s[1]: must be between 0 and 100 m/s, got -1"},
        BadSweep{"UnknownPad", "fixed: {soil: fjs1_lp, impact_speed_m_s: 1}\ngrid: {pad: [flat, hexagon_xl]}\n",
                 "grid.pad[1]: pads: unknown name 'hexagon_xl'"},
        BadSweep{"NoSpeed", "fixed: {pad: flat, soil: fjs1_lp}\n", "impact_speed_m_s: not set"},
        BadSweep{"BadTraces", "traces: some\nfixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1}\n",
                 "traces: must be none, decimated or full"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(Sweep, FailedDropsAreRecordedWithTheirReason) {
  const SweepPlan plan = LoadSweepPlan(Write("s.yaml", kSmallSweep));
  const SweepRunSummary s = RunSweep(plan, (dir_ / "out").string(), Quiet(2));
  EXPECT_EQ(s.computed, 80);
  EXPECT_EQ(s.failed, 40);
  const std::vector<DropRecord> records = Records(dir_ / "out");
  ASSERT_EQ(records.size(), 80u);
  for (const DropRecord& r : records) {
    const bool tiny_zeta = r.zeta_N_cm3 < 1e-3;
    EXPECT_EQ(r.ok, !tiny_zeta) << r.drop_id;
    if (!r.ok) {
      EXPECT_NE(r.failure.find("did not stop"), std::string::npos) << r.failure;
      EXPECT_TRUE(std::isnan(r.final_penetration_m));
    } else {
      EXPECT_GT(r.final_penetration_m, 0.0);
      EXPECT_LE(r.trace.size(), 16u);
      EXPECT_GE(r.trace.size(), 3u);
    }
  }
}

TEST_F(Sweep, OneThreadTwoThreadsAndInMemoryAgreeBitForBit) {
  const SweepPlan plan = LoadSweepPlan(Write("s.yaml", kSmallSweep));
  RunSweep(plan, (dir_ / "one").string(), Quiet(1));
  RunSweep(plan, (dir_ / "two").string(), Quiet(2));
  ExpectSameRecords(Records(dir_ / "one"), Records(dir_ / "two"));
  std::vector<DropRecord> memory = RunSweepInMemory(plan, 2);
  const std::vector<DropRecord> stored = Records(dir_ / "one");
  ASSERT_EQ(memory.size(), stored.size());
  for (size_t i = 0; i < memory.size(); ++i) EXPECT_TRUE(SameRecord(memory[i], stored[i]));
}

TEST_F(Sweep, ShardsMergedEqualTheSingleRun) {
  const std::string file = Write("s.yaml", kSmallSweep);
  ASSERT_EQ(Touchdown("sweep " + file + " --out " + (dir_ / "all").string() + " --progress none").status, 0);
  for (int i = 0; i < 3; ++i) {
    const CliResult r = Touchdown("sweep " + file + " --out " + (dir_ / ("shard" + std::to_string(i))).string() +
                            " --shard " + std::to_string(i) + "/3 --threads 1 --progress none");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  EXPECT_LT(StoredRows(dir_ / "shard0"), 80);
  // Merging two shards leaves drops missing and says so; the third completes the set.
  CliResult m = Touchdown("merge " + (dir_ / "shard0").string() + " " + (dir_ / "shard1").string() + " --out " +
                    (dir_ / "merged").string());
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_NE(m.out.find("missing"), std::string::npos) << m.out;
  m = Touchdown("merge " + (dir_ / "shard1").string() + " " + (dir_ / "shard2").string() + " --out " +
                (dir_ / "merged").string());
  ASSERT_EQ(m.status, 0) << m.err;
  ExpectSameRecords(Records(dir_ / "merged"), Records(dir_ / "all"));
  // A shard of another sweep is refused.
  std::string other = kSmallSweep;
  other.replace(other.find("seed: 11"), 8, "seed: 99");
  ASSERT_EQ(Touchdown("sweep " + Write("other.yaml", other) + " --out " + (dir_ / "other").string() +
                      " --shard 0/3 --progress none")
                .status,
            0);
  m = Touchdown("merge " + (dir_ / "shard0").string() + " " + (dir_ / "other").string() + " --out " +
                (dir_ / "bad").string());
  EXPECT_EQ(m.status, 2);
  EXPECT_NE(m.err.find("not shards of one sweep"), std::string::npos) << m.err;
  // Each shard once: a directory named twice, or a copy of a shard beside it, is refused (its
  // drops would count once and hide a missing shard) and nothing is written.
  m = Touchdown("merge " + (dir_ / "shard0").string() + " " + (dir_ / "." / "shard0").string() + " --out " +
                (dir_ / "twice").string());
  EXPECT_EQ(m.status, 2);
  EXPECT_NE(m.err.find("given twice"), std::string::npos) << m.err;
  fs::copy(dir_ / "shard0", dir_ / "shard0_copy", fs::copy_options::recursive);
  m = Touchdown("merge " + (dir_ / "shard0").string() + " " + (dir_ / "shard0_copy").string() + " --out " +
                (dir_ / "twice").string());
  EXPECT_EQ(m.status, 2);
  EXPECT_NE(m.err.find("holds shard 0/3, as " + (dir_ / "shard0").string() + " does: two copies of one shard"),
            std::string::npos)
      << m.err;
  EXPECT_FALSE(fs::exists(dir_ / "twice"));
}

TEST_F(Sweep, MpirunTwoRanksEqualsTheSingleProcess) {
#ifndef TOUCHDOWN_TEST_WITH_MPI
  GTEST_SKIP() << "touchdown was built without MPI (TOUCHDOWN_WITH_MPI=OFF)";
#endif
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun is not installed";
  const std::string file = Write("s.yaml", kSmallSweep);
  const SweepPlan plan = LoadSweepPlan(file);
  RunSweep(plan, (dir_ / "single").string(), Quiet(2));
  // CI runs as root in a 2-core container: allow root and more ranks than cores. In the
  // sanitized build, LeakSanitizer is off for the ranks only: OpenMPI keeps allocations until
  // exit from plugins it has already unloaded, so they cannot even be named in a suppression
  // (ASan and UBSan stay on; ASAN_OPTIONS means nothing to an uninstrumented build).
  const std::string mpirun =
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 "
      "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" mpirun --allow-run-as-root -np 2 ";
  const CliResult r = Shell(mpirun + TOUCHDOWN_BINARY + " sweep " + file + " --out " + (dir_ / "mpi").string() +
                      " --threads 1 --progress lines");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("on 2 rank(s)"), std::string::npos) << r.out;
  ExpectSameRecords(Records(dir_ / "mpi"), Records(dir_ / "single"));
  // Failures are reported once each, by rank 0.
  size_t lines = 0;
  for (size_t p = 0; (p = r.err.find("failed:", p)) != std::string::npos; ++p) ++lines;
  EXPECT_EQ(lines, 40u) << r.err;
}

TEST_F(Sweep, KilledMidRunAndRestartedEndsWithExactlyTheFullSet) {
  const std::string file = Write("long.yaml", kQuickSweep);
  const SweepPlan plan = LoadSweepPlan(file);
  const int64_t total = plan.size();
  const fs::path out = dir_ / "killed";
  // Kill twice at different points, then let the third run finish.
  for (int64_t threshold : {int64_t{1}, total / 3}) {
    const pid_t pid = Spawn({"sweep", file, "--out", out.string(), "--threads", "1", "--batch", "16", "--progress",
                             "none"});
    ASSERT_GT(pid, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (StoredRows(out) < threshold && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep finished before it could be killed";
    const int64_t stored = StoredRows(out);
    EXPECT_GE(stored, threshold);
    EXPECT_LT(stored, total);
  }
  const CliResult r = Touchdown("sweep " + file + " --out " + out.string() + " --progress none");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("already done"), std::string::npos);
  RunSweep(plan, (dir_ / "clean").string(), Quiet(2));
  const std::vector<DropRecord> killed = Records(out), clean = Records(dir_ / "clean");
  ASSERT_EQ(killed.size(), static_cast<size_t>(total));  // none lost, none duplicated (primary key)
  ExpectSameRecords(killed, clean);
  // Running it again computes nothing.
  EXPECT_EQ(RunSweep(plan, out.string(), Quiet(1)).computed, 0);
}

TEST_F(Sweep, ResumingWithAChangedSweepIsRefused) {
  const std::string file = Write("s.yaml", kSmallSweep);
  RunSweep(LoadSweepPlan(file), (dir_ / "out").string(), Quiet(1));
  std::string changed = kSmallSweep;
  changed.replace(changed.find("count: 4"), 8, "count: 5");
  EXPECT_THROW(RunSweep(LoadSweepPlan(Write("s.yaml", changed)), (dir_ / "out").string(), Quiet(1)), InputError);
  SweepRunOptions shard = Quiet(1);
  shard.shard = ParseShard("1/2");
  EXPECT_THROW(RunSweep(LoadSweepPlan(Write("s.yaml", kSmallSweep)), (dir_ / "out").string(), shard), InputError);
  EXPECT_THROW(ParseShard("2/2"), InputError);
  EXPECT_THROW(ParseShard("1-2"), InputError);
}

TEST_F(Sweep, ExportWritesTheDatasetFormatAndReadsBackIdentical) {
  const std::string file = Write("s.yaml", kSmallSweep);
  const CliResult r = Touchdown("sweep " + file + " --out " + (dir_ / "out").string() + " --progress none");
  ASSERT_EQ(r.status, 0) << r.err;
  const CliResult e = Touchdown("export " + (dir_ / "out").string() + " --to " + (dir_ / "dataset").string());
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NE(e.out.find("40 failed drops listed in failed.csv"), std::string::npos) << e.out;
  const Dataset back = ReadDataset((dir_ / "dataset").string());
  const std::vector<DropRecord> records = Records(dir_ / "out");
  size_t k = 0;
  for (const DropRecord& rec : records) {
    if (!rec.ok) continue;
    ASSERT_LT(k, back.drops.size());
    const DatasetDrop& d = back.drops[k++];
    EXPECT_EQ(d.drop_id, rec.drop_id);
    EXPECT_EQ(d.pad, rec.pad);
    EXPECT_EQ(d.impact_speed_m_s, rec.impact_speed_m_s);
    EXPECT_EQ(d.pad_mass_kg, rec.pad_mass_kg);
    EXPECT_EQ(d.gravity_m_s2, rec.gravity_m_s2);
    EXPECT_EQ(*d.final_penetration_m, rec.final_penetration_m);
    EXPECT_EQ(*d.peak_force_N, rec.peak_force_N);
    EXPECT_EQ(*back.ExtraNumber(d, "mean_conversion_rate_W"), rec.mean_conversion_rate_W);
    ASSERT_EQ(d.trace.size(), rec.trace.size());
    for (size_t i = 0; i < d.trace.size(); ++i) {
      EXPECT_EQ(d.trace.t_s[i], rec.trace[i].t_s);
      EXPECT_EQ(d.trace.force_N[i], rec.trace[i].force_N);
    }
  }
  EXPECT_EQ(k, back.drops.size());
  // Full traces are simulated again and agree with the stored (decimated) samples.
  ExportOptions full;
  full.full_traces = true;
  const Dataset resimulated = SweepToDataset((dir_ / "out").string(), full);
  ASSERT_EQ(resimulated.drops.size(), back.drops.size());
  size_t full_samples = 0, stored_samples = 0;
  for (size_t i = 0; i < back.drops.size(); ++i) {
    full_samples += resimulated.drops[i].trace.size();
    stored_samples += back.drops[i].trace.size();
    EXPECT_EQ(resimulated.drops[i].trace.force_N.back(), back.drops[i].trace.force_N.back());
    EXPECT_EQ(resimulated.drops[i].trace.t_s.front(), back.drops[i].trace.t_s.front());
  }
  EXPECT_GT(full_samples, stored_samples);  // some traces were longer than trace_max_samples
  EXPECT_TRUE(resimulated.drops[3].final_penetration_m == back.drops[3].final_penetration_m);
}

TEST(SweepDecimation, KeepsEndsAndPeak) {
  std::vector<DropSample> trace;
  for (int i = 0; i < 100; ++i) trace.push_back({i * 1e-3, i * 1e-4, 0.0, i == 37 ? 500.0 : static_cast<double>(i)});
  const std::vector<DropSample> d = DecimateTrace(trace, 10);
  ASSERT_EQ(d.size(), 10u);
  EXPECT_EQ(d.front().t_s, 0.0);
  EXPECT_EQ(d.back().t_s, trace.back().t_s);
  bool peak = false;
  for (const DropSample& s : d) peak |= s.force_N == 500.0;
  EXPECT_TRUE(peak);
  EXPECT_EQ(DecimateTrace(trace, 200).size(), 100u);
}

TEST(ResultsDbSerialisation, RecordsSurviveTheMpiMessageFormat) {
  DropRecord r;
  r.index = 42;
  r.drop_id = "d42";
  r.ok = false;
  r.failure = "the pad did not stop";
  r.pad = "flat";
  r.final_penetration_m = std::nan("");
  r.trace = {{0.0, 0.0, 1.0, 0.0}, {1e-3, 1e-3, 0.9, 12.5}};
  const std::vector<DropRecord> back = DeserializeRecords(SerializeRecords({r, r}));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_TRUE(SameRecord(back[1], r));
}


// ---- Hardening: resolution caps and bad inputs refused at load ----

TEST_F(Sweep, GridCountsAndDropTotalsAreCappedAtLoad) {
  // A hand-written count of 1e9 would allocate 8 GB of grid values.
  const std::string base = "schema_version: 1\ntype: sweep\nfixed: {pad: flat, soil: fjs1_lp}\n";
  try {
    LoadSweepPlan(Write("count.yaml", base + "grid: {impact_speed_m_s: {from: 0.5, to: 2, count: 1000000000}}\n"));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grid.impact_speed_m_s.count: must be at most 100000, got 1000000000"),
              std::string::npos)
        << e.what();
  }
  // 1e5 speeds x 1e5 masses x 1e5 gravities x 1e9 samples overflows int64: refused, counted in doubles.
  try {
    LoadSweepPlan(Write("many.yaml", base + "grid:\n  impact_speed_m_s: {from: 0.5, to: 2, count: 100000}\n"
                                            "  pad_mass_kg: {from: 1, to: 2, count: 100000}\n"
                                            "  gravity_m_s2: {from: 1, to: 10, count: 100000}\n"
                                            "random: {samples: 1000000000, seed: 1, zeta_N_cm3: {uniform: [1, 5]}}\n"));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grid: the sweep has too many drops (1e+24, at most 2^40)"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(Sweep, DropOverItsWallClockLimitIsRecordedAsFailedWithTheReason) {
  const std::string body = "schema_version: 1\ntype: sweep\nfixed: {pad: flat, soil: fjs1_lp}\n"
                           "grid: {impact_speed_m_s: [0.7, 1.5]}\n";
  SweepPlan plan = LoadSweepPlan(Write("s.yaml", body));
  EXPECT_EQ(plan.rig.integrator.max_wall_time_s, 0.0);  // the default: none (opt-in, load-dependent)
  EXPECT_EQ(plan.rig.integrator.max_rhs_evaluations, kDefaultMaxDropEvaluations);
  EXPECT_EQ(LoadSweepPlan(Write("none.yaml", "max_drop_wall_time_s: 0\n" + body)).rig.integrator.max_wall_time_s, 0.0);
  EXPECT_THROW(LoadSweepPlan(Write("neg.yaml", "max_drop_wall_time_s: -1\n" + body)), InputError);
  // The limit decides whether a drop finishes, never what it computes: not in the digest.
  const std::string digest = plan.DigestText();
  plan.rig.integrator.max_wall_time_s = 1e-9;
  EXPECT_EQ(plan.DigestText(), digest);
  const std::vector<DropRecord> records = RunSweepInMemory(plan, 2);
  ASSERT_EQ(records.size(), 2u);
  for (const DropRecord& r : records) {
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.failure.find("wall-clock limit exceeded"), std::string::npos) << r.failure;
  }
  // Through the command line: --max-drop-wall-time overrides the file; the run itself succeeds.
  const CliResult cli = Touchdown("sweep " + (dir_ / "s.yaml").string() + " --out " + (dir_ / "cli").string() +
                                  " --max-drop-wall-time 1e-9 --threads 1 --progress lines");
  ASSERT_EQ(cli.status, 0) << cli.err;
  EXPECT_NE(cli.out.find("2 failed"), std::string::npos) << cli.out;
  EXPECT_NE(cli.err.find("failed: wall-clock limit exceeded"), std::string::npos) << cli.err;
  // Recorded as load-dependent: in the meta table and in each failed drop's reason and limit.
  const ResultsDb db(ResultsDbPath((dir_ / "cli").string()));
  EXPECT_EQ(db.Meta().at("load_dependent_failures").rfind("yes", 0), 0u) << db.Meta().at("load_dependent_failures");
  for (const DropRecord& r : db.ReadAll(false)) {
    EXPECT_EQ(r.failure_limit, "max_wall_time_s");
    EXPECT_EQ(r.failure_limit_value, 1e-9);
    EXPECT_NE(r.failure.find("load-dependent"), std::string::npos) << r.failure;
  }
}

}  // namespace
