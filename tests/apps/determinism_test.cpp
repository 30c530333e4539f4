// Determinism: the same inputs give bit-identical outputs across runs, thread counts
// and process counts. The touchdown executable is run as a user would; files are compared
// byte for byte and the sweep databases value by value (doubles by their bit patterns).
// Complements tests/drop_tests/sweep/sweep_test.cpp (in-process thread counts, MPI ranks, a killed
// and restarted sweep).
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "tests/apps/robustness_cli.h"

namespace touchdown::testing_cli {
namespace {

// Every regular file under `root` (relative path -> bytes), optionally skipping an extension.
std::map<std::string, std::string> Tree(const fs::path& root, const std::string& skip_extension = "") {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && (skip_extension.empty() || e.path().extension() != skip_extension))
      files[fs::relative(e.path(), root).string()] = Slurp(e.path());
  return files;
}

void ExpectSameTree(const fs::path& a, const fs::path& b, const std::string& skip_extension = "") {
  const auto ta = Tree(a, skip_extension), tb = Tree(b, skip_extension);
  ASSERT_FALSE(ta.empty()) << a;
  std::vector<std::string> na, nb;
  for (const auto& [k, v] : ta) na.push_back(k);
  for (const auto& [k, v] : tb) nb.push_back(k);
  ASSERT_EQ(na, nb);
  for (const auto& [name, bytes] : ta) EXPECT_TRUE(bytes == tb.at(name)) << name << " differs";
}

// Every row of `table` as text, each value tagged with its SQLite type; REAL values as the hex
// of their bits, so that -0.0 vs 0.0 or a last-bit difference shows.
std::vector<std::string> Dump(const fs::path& db_path, const std::string& table, const std::string& order) {
  sqlite3* db = nullptr;
  std::vector<std::string> rows;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    ADD_FAILURE() << "cannot open " << db_path;
    sqlite3_close(db);
    return rows;
  }
  sqlite3_stmt* st = nullptr;
  const std::string sql = "SELECT * FROM " + table + " ORDER BY " + order;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr) != SQLITE_OK) {
    ADD_FAILURE() << sqlite3_errmsg(db);
  } else {
    while (sqlite3_step(st) == SQLITE_ROW) {
      std::string row;
      for (int c = 0; c < sqlite3_column_count(st); ++c) {
        row += std::string(sqlite3_column_name(st, c)) + "=";
        switch (sqlite3_column_type(st, c)) {
          case SQLITE_INTEGER:  // appended in two steps: GCC 12 warns (-Wrestrict) on "literal" + string
            row += 'i';
            row += std::to_string(sqlite3_column_int64(st, c));
            break;
          case SQLITE_FLOAT: {
            const double v = sqlite3_column_double(st, c);
            uint64_t bits;
            std::memcpy(&bits, &v, sizeof bits);
            char hex[24];
            std::snprintf(hex, sizeof hex, "r%016llx", static_cast<unsigned long long>(bits));
            row += hex;
            break;
          }
          case SQLITE_NULL: row += "null"; break;
          default: {  // text and blobs byte for byte
            const auto* p = static_cast<const char*>(sqlite3_column_blob(st, c));
            row += 'b';
            row.append(p ? p : "", p ? static_cast<size_t>(sqlite3_column_bytes(st, c)) : 0);
          }
        }
        row += ";";
      }
      rows.push_back(row);
    }
  }
  sqlite3_finalize(st);
  sqlite3_close(db);
  return rows;
}

void ExpectSameDb(const fs::path& a, const fs::path& b) {
  for (const auto& [table, order] : {std::pair<std::string, std::string>{"drops", "drop_index"}, {"traces", "drop_index"}}) {
    const std::vector<std::string> ra = Dump(a / "results.sqlite", table, order),
                                   rb = Dump(b / "results.sqlite", table, order);
    ASSERT_FALSE(ra.empty()) << a << " " << table;
    ASSERT_EQ(ra.size(), rb.size()) << table;
    for (size_t i = 0; i < ra.size(); ++i) EXPECT_EQ(ra[i], rb[i]) << table << " row " << i;
  }
}

// 2 pads x 3 speeds x 2 zetas x 3 random samples = 36 drops with full traces; zeta 1e-6 never
// stops the pad, so half of them fail and must fail identically.
const char* kSweep = R"(schema_version: 1
type: sweep
name: determinism
traces: full
fixed: {soil: fjs1_lp}
grid:
  pad: [flat, curved]
  impact_speed_m_s: {from: 0.6, to: 1.8, count: 3}
  zeta_N_cm3: [0.000001, 3.5]
random: {samples: 3, seed: 2024, pad_mass_kg: {uniform: [1.0, 2.5]}, gravity_m_s2: {choice: [1.62, 3.71, 9.81]}}
)";

TEST(Determinism, SameDropTwiceIsBitIdentical) {
  Sandbox box("determinism_drop");
  const std::string args = "drop --pad curved --soil fjs1_cp --speed 1.3 --mass 2.1 --gravity 3.71 --trace ";
  const CliRun a = box.Touchdown(args + "a.csv"), b = box.Touchdown(args + "b.csv");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(Slurp(box.dir() / "a.csv"), Slurp(box.dir() / "b.csv"));
  EXPECT_GT(Slurp(box.dir() / "a.csv").size(), 100u);
  // The free 6-DOF pad, straight down (tilted free drops take too long for every CI run).
  const std::string free = "drop --pad flat --soil fjs1_lp --speed 1.0 --free --trace ";
  const CliRun fa = box.Touchdown(free + "fa.csv"), fb = box.Touchdown(free + "fb.csv");
  ASSERT_EQ(fa.status, 0) << fa.err;
  EXPECT_EQ(fa.out, fb.out);
  EXPECT_EQ(Slurp(box.dir() / "fa.csv"), Slurp(box.dir() / "fb.csv"));
  // The 3D force on a tilted, sliding, spinning pad.
  const std::string force = "force --pad curved --soil fjs1_lp --depth 0.008 --tilt-deg 12 --tilt-axis y "
                            "--velocity 0.4,-0.1,-1 --omega 0.5,1,0";
  const CliRun ra = box.Touchdown(force), rb = box.Touchdown(force);
  ASSERT_EQ(ra.status, 0) << ra.err;
  EXPECT_EQ(ra.out, rb.out);
}

TEST(Determinism, CampaignTwiceWritesIdenticalFiles) {
  Sandbox box("determinism_campaign");
  const std::string scenario = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/sutoh2017_single_footpad.yaml";
  for (const char* out : {"one", "two"}) {
    const CliRun r = box.Touchdown("campaign " + ShellQuote(scenario) + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // Tables, traces, JSON and the resolved scenario; the PNG plots are gnuplot's business.
  ExpectSameTree(box.dir() / "one", box.dir() / "two", ".png");
}

TEST(Determinism, ShortLanderDropTwiceIsBitIdentical) {
  Sandbox box("determinism_lander");
  box.Write("lander.yaml",
            "schema_version: 1\ntype: lander\nlander: sutoh2017_lander\ngravity_m_s2: 1.62\n"
            "ground: {soil: fjs1_lp, slope_deg: 5}\ninitial: {touchdown_speed_m_s: 1.0, roll_deg: 2}\n"
            "simulation: {duration_s: 0.03}\n");  // 30 ms of pad contact: seconds even under ASan
  for (const char* out : {"one", "two"}) {
    const CliRun r = box.Touchdown(std::string("lander lander.yaml --out ") + out);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  ExpectSameTree(box.dir() / "one", box.dir() / "two", ".png");
}

// Runs sweep.yaml in `box` with `options` at 1 and 2 threads (t1, t2) and as two shards merged
// (merged): the three databases must be equal value by value.
void ExpectSameAtAnyThreadCountAndShards(Sandbox& box, const std::string& options) {
  auto run = [&](const std::string& extra) {
    const CliRun r = box.Touchdown("sweep sweep.yaml --progress none " + options + " " + extra);
    EXPECT_EQ(r.status, 0) << extra << ": " << r.err;
  };
  run("--out t1 --threads 1");
  run("--out t2 --threads 2");
  run("--out s0 --shard 0/2 --threads 2");
  run("--out s1 --shard 1/2 --threads 1");
  const CliRun m = box.Touchdown("merge s0 s1 --out merged");
  ASSERT_EQ(m.status, 0) << m.err;
  ExpectSameDb(box.dir() / "t1", box.dir() / "t2");
  ExpectSameDb(box.dir() / "t1", box.dir() / "merged");
}

TEST(Determinism, SweepIsBitIdenticalForThreadsShardsAndMerge) {
  Sandbox box("determinism_sweep");
  box.Write("sweep.yaml", kSweep);
  ExpectSameAtAnyThreadCountAndShards(box, "");
  // Half the drops fail (zeta 1e-6): the failures are part of the result.
  const std::vector<std::string> rows = Dump(box.dir() / "t1" / "results.sqlite", "drops", "drop_index");
  ASSERT_EQ(rows.size(), 36u);
  EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [](const std::string& r) { return r.find("status=bfailed") != std::string::npos; }),
            18);
  // The exported datasets (shortest round-trip numbers) agree byte for byte.
  for (const char* dir : {"t1", "t2", "merged"}) {
    const CliRun r = box.Touchdown(std::string("export ") + dir + " --to " + dir + "_dataset --full-traces");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  ExpectSameTree(box.dir() / "t1_dataset", box.dir() / "t2_dataset");
  ExpectSameTree(box.dir() / "t1_dataset", box.dir() / "merged_dataset");
}

// The default per-drop limit counts right-hand-side evaluations, not seconds,
// so which drops run out of it is the same at 1 and 2 threads, in shards, under any load.
TEST(Determinism, EvaluationLimitFailsTheSameDropsAtAnyThreadCount) {
  Sandbox box("determinism_limit");
  box.Write("sweep.yaml", R"(schema_version: 1
type: sweep
name: limit
traces: decimated
trace_max_samples: 8
fixed: {pad: hex, soil: fjs1_lp}
grid:
  tilt_deg: [0, 3]
  impact_speed_m_s: {from: 0.4, to: 1.6, count: 6}
)");
  ExpectSameAtAnyThreadCountAndShards(box, "--max-drop-evaluations 150");
  const std::vector<std::string> rows = Dump(box.dir() / "t1" / "results.sqlite", "drops", "drop_index");
  ASSERT_EQ(rows.size(), 12u);
  const auto failed = std::count_if(rows.begin(), rows.end(), [](const std::string& r) {
    return r.find("failure_limit=bmax_rhs_evaluations") != std::string::npos;
  });
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, 12);
}

}  // namespace
}  // namespace touchdown::testing_cli
