// The commands that draw plots, run as a user runs them. An --out holding a
// quote, a shell injection attempt, spaces or non-ASCII characters, or a relative path, gives
// complete PNGs and runs nothing else; a sweep whose drops all failed still plots; a write
// failure (a file size limit standing in for a full disk) or a missing gnuplot is exit 2 with
// one line and leaves no output directory.
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/apps/robustness_cli.h"

namespace touchdown::testing_cli {
namespace {

// The PNG signature at the start and the IEND chunk at the very end.
bool CompletePng(const fs::path& file) {
  const std::string bytes = Slurp(file);
  const std::string signature = "\x89PNG\r\n\x1a\n";
  const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return bytes.size() > 20 && bytes.compare(0, 8, signature) == 0 && bytes.compare(bytes.size() - 12, 12, iend) == 0;
}

bool AnyPwned(const fs::path& dir) {
  if (fs::exists("PWNED")) return true;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename() == "PWNED") return true;
  return false;
}

const std::string kSmallSweep =
    "schema_version: 1\ntype: sweep\ntraces: none\nfixed: {soil: fjs1_lp}\n"
    "grid: {pad: [flat, curved], impact_speed_m_s: [0.7, 1.0]}\n";
// zeta 1e-6 N/cm^3: the pad never stops, every drop is recorded as failed.
const std::string kFailedSweep =
    "schema_version: 1\ntype: sweep\nfixed: {pad: flat, soil: fjs1_lp}\n"
    "grid: {impact_speed_m_s: [1], zeta_N_cm3: [0.000001]}\n";
const std::string kShortLander =
    "schema_version: 1\ntype: lander\nlander: sutoh2017_lander\nground: {soil: fjs1_lp}\n"
    "initial: {touchdown_speed_m_s: 1.0}\nsimulation: {duration_s: 0.03}\n";
const std::string kInjection = "x'; touch PWNED; echo '";

std::string Campaign() {
  return ShellQuote(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/sutoh2017_single_footpad.yaml");
}

TEST(PlotOutputs, TradeOutWithQuotesInjectionNonAsciiOrRelativePathPlotsAndRunsNothingElse) {
  Sandbox box("plot_trade_out");
  box.Write("sweep.yaml", kSmallSweep);
  for (const std::string& out : {std::string("it's"), kInjection, std::string("with space é ✓"),
                                std::string("results/pad_trade")}) {
    SCOPED_TRACE(out);
    if (out == "results/pad_trade") fs::create_directories(box.dir() / "results");
    const CliRun r = box.Touchdown("trade sweep.yaml --out " + ShellQuote(out));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(CompletePng(box.dir() / out / "plots" / "trade.png"));
    EXPECT_TRUE(CompletePng(box.dir() / out / "plots" / "pareto.png"));
    EXPECT_FALSE(fs::exists(box.dir() / out / "plots" / "gnuplot.log"));
  }
  EXPECT_FALSE(AnyPwned(box.dir()));
}

TEST(PlotOutputs, CampaignAndLanderWithAnInjectionAttemptInOut) {
  Sandbox box("plot_injection");
  box.Write("lander.yaml", kShortLander);
  const std::string out = ShellQuote(kInjection);
  CliRun r = box.Touchdown("campaign " + Campaign() + " --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string figure : {"fig3_time_histories", "fig4_peaks", "fig6_force_penetration", "fig7_paper_checks"}) {
    EXPECT_TRUE(CompletePng(box.dir() / kInjection / "plots" / (figure + ".png"))) << figure;
    EXPECT_GT(fs::file_size(box.dir() / kInjection / "plots" / (figure + ".svg")), 1000u) << figure;
  }
  r = box.Touchdown("lander lander.yaml --out " + ShellQuote(kInjection + " lander"));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string figure : {"penetration", "attitude", "loads"}) {
    const fs::path plots = box.dir() / (kInjection + " lander") / "plots";
    EXPECT_TRUE(CompletePng(plots / (figure + ".png"))) << figure;
    EXPECT_GT(fs::file_size(plots / (figure + ".svg")), 1000u) << figure;
  }
  EXPECT_FALSE(AnyPwned(box.dir()));
}

// The figures as a reader sees them (issue: figures reviewed as for a paper): each script draws
// an SVG beside its PNG, soils by their display names, keys that cover no panel.
TEST(PlotOutputs, CampaignFiguresNameSoilsAndDrawEveryFigureAsSvgToo) {
  Sandbox box("plot_campaign_review");
  const CliRun r = box.Touchdown("campaign " + Campaign() + " --out out");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string script = Slurp(box.dir() / "out" / "plots" / "campaign.gp");
  for (const std::string figure : {"fig3_time_histories", "fig4_peaks", "fig6_force_penetration", "fig7_paper_checks"})
    EXPECT_NE(script.find("set output 'plots/" + figure + ".svg'"), std::string::npos) << figure;
  EXPECT_NE(script.find("set terminal svg"), std::string::npos);
  EXPECT_NE(script.find("flat, FJS-1 CP"), std::string::npos) << "soil display names in the keys";
  EXPECT_EQ(script.find("fjs1_cp'"), std::string::npos) << "no raw soil id as a title";
  EXPECT_EQ(script.find("key outside right"), std::string::npos) << "no key taking a quarter of the width";
  EXPECT_NE(script.find("curved over flat penetration lp"), std::string::npos) << "check names in words";
  EXPECT_NE(script.find("with yerrorbars"), std::string::npos) << "the experiments' bars";
  EXPECT_NE(script.find("fs transparent pattern"), std::string::npos) << "closely packed bars hatched";
}

// Case B: pads 2 and 4 and roll and pitch move together; each trace keeps its own style, a note
// says which coincide, the paper's band is on the scale, and the traces break at the rest event.
TEST(PlotOutputs, LanderFiguresKeepCoincidentTracesVisibleAndTheBandOnScale) {
  Sandbox box("plot_lander_review");
  const CliRun r = box.Touchdown("lander " + ShellQuote(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/lander_case_B.yaml") +
                                 " --out out");
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path plots = box.dir() / "out" / "plots";
  const std::string script = Slurp(plots / "lander.gp");
  EXPECT_NE(script.find("pads 2 and 4 coincide"), std::string::npos) << script;
  EXPECT_NE(script.find("roll and pitch coincide"), std::string::npos) << script;
  for (const char* dash : {"dt 1", "dt 2", "dt 4"}) EXPECT_NE(script.find(dash), std::string::npos) << dash;
  EXPECT_NE(script.find("'at rest'"), std::string::npos);
  EXPECT_EQ(script.find("key outside"), std::string::npos);
  // The attitude's y range holds the band at -0.5 deg.
  const size_t attitude = script.find("set output 'plots/attitude.png'");
  const size_t yrange = script.find("set yrange [", attitude);
  ASSERT_NE(yrange, std::string::npos);
  EXPECT_LT(std::stod(script.substr(yrange + 12)), -0.5) << script.substr(yrange, 40);
  // The events that switch how the pads' forces are computed are marked (pad 3's capture before
  // the rest, the rest), and the leg panel says which side of its drawn zero line is tension
  // (the legs pull while the body rebounds: tests/drop_tests/scenario/lander_rest_loads_test.cpp).
  EXPECT_NE(script.find("\"pad 3 held\\nat 162.56 ms\""), std::string::npos) << script;
  EXPECT_NE(script.find("the holds carry"), std::string::npos) << script;
  EXPECT_NE(script.find("(< 0: tension)"), std::string::npos) << script;
  EXPECT_NE(script.find("set xzeroaxis"), std::string::npos) << script;
  // A blank line at each event's repeated instant breaks the lines there: no drawn segment joins
  // the state before a switch to the state after it.
  std::istringstream rows(Slurp(plots / "data" / "trace.csv"));
  std::string row, previous;
  int breaks = 0;
  std::getline(rows, row);  // the header
  while (std::getline(rows, row)) {
    if (row.empty()) {
      ++breaks;
    } else if (!previous.empty()) {
      EXPECT_NE(row.substr(0, row.find(',')), previous.substr(0, previous.find(','))) << "a segment across a switch at " << row;
    }
    previous = row;
  }
  EXPECT_GE(breaks, 2) << "pad 3's capture and the rest";
}

TEST(PlotOutputs, StudyHistogramsCountInWholeLandingsAndEmptyMapCellsAreHatched) {
  Sandbox box("plot_study_review");
  box.Write("level.yaml",
            "schema_version: 1\ntype: stability\nname: level_quick\nlander: {scenario: lander_case_A}\n"
            "random: {samples: 3, seed: 3, impact_speed_m_s: {uniform: [0.6, 1.0]},\n"
            "         gravity_m_s2: {uniform: [1.62, 9.81]}}\n"
            "study: {map: {x: impact_speed_m_s, y: gravity_m_s2, bins: [3, 3]}}\n");
  const CliRun r = box.Touchdown("stability level.yaml --out out --threads 2 --progress none");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string script = Slurp(box.dir() / "out" / "plots" / "study.gp");
  EXPECT_NE(script.find("set ytics 0, 1\nset format y '%.0f'"), std::string::npos) << script;
  EXPECT_NE(script.find("fillstyle pattern"), std::string::npos) << "empty cells hatched";
  EXPECT_EQ(script.find("'#f7f7f7'"), std::string::npos) << "no white in the probability scale";
  EXPECT_NE(script.find("set output 'plots/histograms.svg'"), std::string::npos);
}

TEST(PlotOutputs, TradeOfASweepWhoseDropsAllFailedPlotsPlaceholders) {
  Sandbox box("plot_trade_failed");
  box.Write("failed.yaml", kFailedSweep);
  const CliRun r = box.Touchdown("trade failed.yaml --out out");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(CompletePng(box.dir() / "out" / "plots" / "trade.png"));
  EXPECT_TRUE(CompletePng(box.dir() / "out" / "plots" / "pareto.png"));
  const std::string script = Slurp(box.dir() / "out" / "plots" / "trade.gp");
  EXPECT_NE(script.find("nothing to plot"), std::string::npos) << script;
  EXPECT_EQ(r.err.find("gnuplot"), std::string::npos) << r.err;
}

// RLIMIT_FSIZE with SIGXFSZ ignored makes writes fail with EFBIG: gnuplot then leaves a
// truncated PNG and exits 0, as on a full disk. The staged output must not appear.
TEST(PlotOutputs, TruncatedPngIsExitTwoAndLeavesNoOutput) {
  Sandbox box("plot_full_disk");
  const CliRun r = box.Touchdown("campaign " + Campaign() + " --out out", "trap '' XFSZ; ulimit -f 40;");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("plots/fig3_time_histories.png"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(box.dir() / "out"));
}

TEST(PlotOutputs, GnuplotMissingIsExitTwoAndLeavesNoOutput) {
  Sandbox box("plot_no_gnuplot");
  fs::create_directories(box.dir() / "empty_bin");
  const CliRun r = box.Touchdown("campaign " + Campaign() + " --out out", "PATH=" + ShellQuote((box.dir() / "empty_bin").string()));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err, "touchdown: gnuplot: not found on the PATH; touchdown draws its plots with gnuplot: install it "
                   "(Debian: apt install gnuplot-nox)\n");
  EXPECT_FALSE(fs::exists(box.dir() / "out"));
}

}  // namespace
}  // namespace touchdown::testing_cli
