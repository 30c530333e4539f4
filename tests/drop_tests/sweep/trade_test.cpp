// The trade study: Pareto fronts against a hand-checked table, aggregation of drops into rows,
// `touchdown trade` on the paper's three pads (curved deepest and gentlest, as the paper), and its
// figures at size (a random-speed sweep of thousands of drops, a trade of ten pads).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include "drop_tests/sweep/sweep_plan.h"
#include "drop_tests/sweep/trade.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::sweep;

TradeRow Row(const std::string& pad, double d, double f) {
  TradeRow r;
  r.pad = pad;
  r.soil = "s";
  r.impact_speed_m_s = 1.0;
  r.drops = 1;
  r.final_penetration_m = d;
  r.peak_force_N = f;
  return r;
}

TEST(TradePareto, NonDominatedRowsOnly) {
  // a (1,3), b (2,2), c (3,1) trade off; d (3,3) is beaten by b; e ties a and is not beaten.
  std::vector<TradeRow> rows = {Row("a", 1, 3), Row("b", 2, 2), Row("c", 3, 1), Row("d", 3, 3), Row("e", 1, 3)};
  MarkParetoFront(rows, {0, 1, 2, 3, 4});
  EXPECT_TRUE(rows[0].pareto);
  EXPECT_TRUE(rows[1].pareto);
  EXPECT_TRUE(rows[2].pareto);
  EXPECT_FALSE(rows[3].pareto);
  EXPECT_TRUE(rows[4].pareto);
}

// Limits: rows outside them are infeasible and off the front, whatever they trade off; the best
// row of a condition is the feasible one furthest inside the limits.
TEST(TradeLimitsTest, InfeasibleRowsLeaveTheFrontAndTheLargestMarginIsBest) {
  std::vector<DropRecord> records;
  const double depth[3] = {0.008, 0.009, 0.016}, force[3] = {228.0, 223.0, 206.0};  // flat, c4, curved at 1 m/s
  const char* pads[3] = {"flat", "c4", "curved"};
  for (int i = 0; i < 3; ++i) {
    DropRecord r;
    r.index = i;
    r.pad = pads[i];
    r.soil = "fjs1_lp";
    r.impact_speed_m_s = 1.0;
    r.ok = true;
    r.final_penetration_m = depth[i];
    r.peak_force_N = force[i];
    r.pad_mass_kg = 1.6;
    records.push_back(r);
  }
  const std::vector<TradeRow> free_rows = TradeTable(records);
  for (const TradeRow& r : free_rows) {
    EXPECT_TRUE(r.feasible && r.pareto) << r.pad;  // no limits: the three trade off, all on the front
    EXPECT_TRUE(std::isnan(r.margin));
    EXPECT_FALSE(r.best);
  }
  TradeLimits limits;
  limits.max_final_penetration_m = 0.015;
  limits.max_peak_force_N = 250.0;
  const std::vector<TradeRow> rows = TradeTable(records, limits);
  ASSERT_EQ(rows.size(), 3u);
  for (const TradeRow& r : rows) {
    const bool curved = r.pad == "curved";
    EXPECT_EQ(r.feasible, !curved) << r.pad;
    EXPECT_EQ(r.pareto, !curved) << r.pad;
    // flat: min(1 - 8/15, 1 - 228/250) = 0.088; c4: min(1 - 9/15, 1 - 223/250) = 0.108 (best).
    const double expected = r.pad == "flat" ? 1.0 - 228.0 / 250.0 : r.pad == "c4" ? 1.0 - 223.0 / 250.0 : 1.0 - 16.0 / 15.0;
    EXPECT_NEAR(r.margin, expected, 1e-12) << r.pad;
    EXPECT_EQ(r.best, r.pad == "c4") << r.pad;
  }
  const nlohmann::json j = TradeJson(rows, limits);
  EXPECT_EQ(j["rows_feasible"], 2);
  EXPECT_EQ(j["rows_on_front"], 2);
  EXPECT_DOUBLE_EQ(j["limits"]["allowable_peak_force_N"].get<double>(), 250.0);
  EXPECT_TRUE(j["limits"]["max_pad_mass_kg"].is_null());
}

TEST(TradeTable, RowsAreMeansOverTheirDropsAndFailuresAreCounted) {
  std::vector<DropRecord> records(3);
  for (int i = 0; i < 3; ++i) {
    records[i].index = i;
    records[i].pad = "flat";
    records[i].soil = "fjs1_lp";
    records[i].impact_speed_m_s = 1.0;
    records[i].ok = i < 2;
    records[i].final_penetration_m = i < 2 ? 0.01 * (i + 1) : std::nan("");
    records[i].peak_force_N = 100.0 * (i + 1);
    records[i].mean_conversion_rate_W = 10.0;
  }
  const std::vector<TradeRow> rows = TradeTable(records);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].drops, 3);
  EXPECT_EQ(rows[0].failed, 1);
  EXPECT_DOUBLE_EQ(rows[0].final_penetration_m, 0.015);
  EXPECT_DOUBLE_EQ(rows[0].peak_force_N, 150.0);
  EXPECT_TRUE(rows[0].pareto);
}

TEST(TradeCli, PaperPadsCurvedIsDeepestGentlestAndOnTheFront) {
  const fs::path dir = fs::temp_directory_path() / ("touchdown_trade_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "t.yaml") << "schema_version: 1\ntype: sweep\ntraces: none\nfixed: {soil: fjs1_lp}\n"
                                   "grid: {pad: [flat, c4, curved], impact_speed_m_s: [0.7, 1.0, 1.5]}\n";
  const std::string cmd = std::string(TOUCHDOWN_BINARY) + " trade " + (dir / "t.yaml").string() + " --out " +
                          (dir / "out").string() + " >/dev/null 2>" + (dir / "err.txt").string();
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0);
  std::ifstream in(dir / "out" / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["rows"].size(), 9u);
  for (double v : {0.7, 1.0, 1.5}) {
    nlohmann::json flat, curved;
    for (const auto& r : j["rows"])
      if (r["impact_speed_m_s"].get<double>() == v) {
        if (r["pad"] == "flat") flat = r;
        if (r["pad"] == "curved") curved = r;
      }
    ASSERT_FALSE(curved.is_null());
    EXPECT_GT(curved["final_penetration_m"].get<double>(), flat["final_penetration_m"].get<double>()) << v;
    EXPECT_LT(curved["peak_force_N"].get<double>(), flat["peak_force_N"].get<double>()) << v;
    EXPECT_LT(curved["mean_conversion_rate_W"].get<double>(), flat["mean_conversion_rate_W"].get<double>()) << v;
    EXPECT_TRUE(curved["pareto"].get<bool>()) << v;
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "trade.csv"));
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    EXPECT_GT(fs::file_size(dir / "out" / "plots" / "trade.png"), 5000u);
    EXPECT_GT(fs::file_size(dir / "out" / "plots" / "pareto.png"), 5000u);
  }
  fs::remove_all(dir);
}

TEST(TradeLander, LanderSweepIsRefusedBeforeAnythingRuns) {
  // In the library: the plan (naming the sweep file and its lander field) and lander records.
  const std::string sweep = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/sweeps/lander_speed_soil.yaml";
  try {
    CheckTradePlan(LoadSweepPlan(sweep));
    ADD_FAILURE() << "accepted a lander sweep";
  } catch (const touchdown::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lander_speed_soil.yaml: lander: trade compares footpads"), std::string::npos)
        << e.what();
  }
  std::vector<DropRecord> records(1);
  records[0].kind = DropKind::kLander;
  records[0].drop_id = "d0";
  EXPECT_THROW(TradeTable(records), touchdown::InputError);
  // From the CLI: exit status 2, one line naming the file, and no output directory.
  const fs::path dir = fs::temp_directory_path() / ("touchdown_trade_lander_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cmd = std::string(TOUCHDOWN_BINARY) + " trade " + sweep + " --out " + (dir / "out").string() +
                          " >/dev/null 2>" + (dir / "err.txt").string();
  const int raw = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 2);
  EXPECT_FALSE(fs::exists(dir / "out"));
  std::ifstream err(dir / "err.txt");
  const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("lander_speed_soil.yaml: lander: "), std::string::npos) << text;
  fs::remove_all(dir);
}

// A feasible row on its condition's front (the figures read only these flags and numbers).
TradeRow PlotRow(const std::string& pad, const std::string& soil, double speed, double scale) {
  TradeRow r;
  r.pad = pad;
  r.soil = soil;
  r.impact_speed_m_s = speed;
  r.drops = 1;
  r.final_penetration_m = 0.01 * speed * scale;
  r.peak_force_N = 200.0 * speed / scale;
  r.mean_conversion_rate_W = 50.0 * speed * speed;
  r.pareto = true;
  return r;
}

struct TradePlotsTest : touchdown::testing_scratch::ScratchDirTest {};

TEST_F(TradePlotsTest, RandomSpeedSweepDrawsDotsAndMediansAndNoFronts) {
  // 1,800 drops at 300 random-like speeds (a row, and a condition, per drop), the mass varying
  // under them: the rows of a series zigzag.
  std::vector<TradeRow> rows;
  for (int i = 0; i < 300; ++i)
    for (const char* soil : {"fjs1_lp", "fjs1_cp"})
      for (const char* pad : {"flat", "c4", "curved"})
        rows.push_back(PlotRow(pad, soil, 0.5 + 2.0 * ((i * 37) % 300) / 300.0, 1.0 + 0.2 * (i % 5)));
  WriteTradePlots(rows, dir_.string());
  const std::string script = Slurp(dir_ / "plots" / "trade.gp");
  EXPECT_TRUE(fs::is_regular_file(dir_ / "plots" / "data" / "flat__fjs1_lp__medians.csv"));
  EXPECT_NE(script.find("'plots/data/flat__fjs1_lp__medians.csv' using 1:($2*1000) with lines"), std::string::npos) << script;
  EXPECT_NE(script.find("'plots/data/flat__fjs1_lp.csv' using 1:($2*1000) with points pt 7 ps 0.35"), std::string::npos);
  // Tics on the speed axis: 0.5 apart, not gnuplot's 0.2 that ran together.
  EXPECT_NE(script.find("set xtics 0.5\n"), std::string::npos);
  // The Pareto panels: one per soil, fronts not drawn past 12 a soil, and said so.
  EXPECT_NE(script.find("set multiplot layout 1,2"), std::string::npos);
  EXPECT_NE(script.find("FJS-1 LP: 300 conditions, fronts not drawn (drawn up to 12)"), std::string::npos);
  EXPECT_EQ(script.find("front_"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "plots" / "pareto.png"));
}

TEST_F(TradePlotsTest, TenPadsTakeTenColoursAndTheKeyItsRows) {
  std::vector<TradeRow> rows;
  const std::vector<std::string> pads = {"flat", "c4", "curved", "r35", "r40", "r45", "r55", "r60", "r65", "r70"};
  for (const std::string& pad : pads)
    for (const double speed : {0.5, 1.0, 1.5}) rows.push_back(PlotRow(pad, "fjs1_lp", speed, 1.0 + pad.size() * 0.1));
  WriteTradePlots(rows, dir_.string());
  const std::string script = Slurp(dir_ / "plots" / "trade.gp");
  std::set<std::string> colours;
  for (const std::string& pad : pads) {
    const std::string series = "'plots/data/" + pad + "__fjs1_lp.csv' using 1:($2*1000) with linespoints lw 2.5 lc rgb '";
    const size_t at = script.find(series);
    ASSERT_NE(at, std::string::npos) << pad;
    colours.insert(script.substr(at + series.size(), 7));
  }
  EXPECT_EQ(colours.size(), pads.size());
  // Ten series (and no limit) in rows of four: three rows, the figure a row (30 pixels) taller.
  EXPECT_NE(script.find("size 1600,630"), std::string::npos) << script.substr(0, 400);
  // The fronts of three speeds, each named by its speed.
  EXPECT_NE(script.find("'1.5 m/s'"), std::string::npos);
}

}  // namespace
