// The diagnosis's figures at the size campaigns are run: synthetic rows (no drop simulated) of a
// short diagnosis, a replicated campaign of 96 drops and one of 200 conditions, drawn by the
// figure writers. Checked in the data files and the gnuplot script they write, and rendered: a bar
// pair a drop up to 25 drops a panel, a bar pair a condition (mean, whiskers at its drops' range,
// held-out drops counted) up to 25 conditions, a scatter past that naming the worst drops; residuals
// as every sample up to 10 held-out drops a panel, as the median and 5-95 % band over time bins past
// that, on one scale.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/gap/diagnose_plots.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::gap {
namespace {

namespace fs = std::filesystem;

// `conditions` conditions of `replicates` drops each; drop r of condition c has NRMSE before
// 0.1 + 0.01 r + 0.001 c and after half that; the last replicate of each condition is held out.
std::vector<GapRow> Rows(int conditions, int replicates) {
  std::vector<GapRow> rows;
  for (int c = 0; c < conditions; ++c)
    for (int r = 0; r < replicates; ++r)
      rows.push_back({"d" + std::to_string(c) + "_" + std::to_string(r), "flat FJS-1 LP " + std::to_string(c) + " m/s",
                      "key" + std::to_string(c), r == replicates - 1, 0.1 + 0.01 * r + 0.001 * c, 0.05 + 0.005 * r + 0.0005 * c,
                      0.01});
  return rows;
}

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

class DiagnosePlots : public testing_scratch::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    fs::create_directories(dir_ / "data");
    fs::create_directories(dir_ / "plots");
  }
  void Render(const std::string& gp, const std::string& png) {
    io::RenderPlots(dir_, {"plots/diagnose.gp", gp, {png}});
    EXPECT_EQ(io::PngProblem(dir_ / png), "");
  }
};

TEST_F(DiagnosePlots, TheLayoutFollowsTheDropsAndConditionsAPanelHolds) {
  EXPECT_EQ(ChooseGapLayout(Rows(12, 1)), GapLayout::kPerDrop);
  EXPECT_EQ(ChooseGapLayout(Rows(25, 1)), GapLayout::kPerDrop);
  EXPECT_EQ(ChooseGapLayout(Rows(12, 4)), GapLayout::kByCondition);  // the shipped campaign, trials: 4
  EXPECT_EQ(ChooseGapLayout(Rows(25, 2)), GapLayout::kByCondition);
  EXPECT_EQ(ChooseGapLayout(Rows(26, 1)), GapLayout::kScatter);
  EXPECT_EQ(ChooseGapLayout(Rows(100, 2)), GapLayout::kScatter);
}

TEST_F(DiagnosePlots, AConditionIsItsDropsMeanWithTheirRangeAndTheHeldOutCounted) {
  ASSERT_EQ(WriteGapPanelData(Rows(12, 4), "vacuum", dir_), GapLayout::kByCondition);
  const io::CsvTable t = io::ReadCsv((dir_ / "data/gap_vacuum.csv").string());
  ASSERT_EQ(t.rows.size(), 12u);
  // Condition 3: before 0.103 + {0, 0.01, 0.02, 0.03}, after half of it.
  const std::vector<std::string>& c3 = t.rows[3];
  EXPECT_EQ(c3[1], "flat FJS-1 LP 3 m/s (4; 1*)");
  EXPECT_NEAR(std::stod(c3[2]), 0.118, 1e-15);
  EXPECT_NEAR(std::stod(c3[3]), 0.103, 1e-15);
  EXPECT_NEAR(std::stod(c3[4]), 0.133, 1e-15);
  EXPECT_NEAR(std::stod(c3[5]), 0.059, 1e-15);
  EXPECT_NEAR(std::stod(c3[6]), 0.0515, 1e-15);
  EXPECT_NEAR(std::stod(c3[7]), 0.0665, 1e-15);
  EXPECT_EQ(c3[9], "4");
  EXPECT_EQ(c3[10], "1");
}

TEST_F(DiagnosePlots, PastTwentyFiveConditionsEachDropIsAPointAndTheWorstAreNamed) {
  std::vector<GapRow> rows = Rows(100, 2);
  rows[17].after = 0.9;  // the worst with the effect
  ASSERT_EQ(WriteGapPanelData(rows, "air", dir_), GapLayout::kScatter);
  const io::CsvTable t = io::ReadCsv((dir_ / "data/gap_air.csv").string());
  ASSERT_EQ(t.rows.size(), 200u);
  size_t named = 0;
  for (const std::vector<std::string>& r : t.rows) named += r[5].empty() ? 0 : 1;
  EXPECT_EQ(named, kNamedWorstDrops);
  EXPECT_EQ(t.rows[17][5], rows[17].drop_label);
  // The next worst: the held-out replicates of the last conditions (after = 0.055 + 0.0005 c).
  EXPECT_EQ(t.rows[199][5], rows[199].drop_label);
  EXPECT_TRUE(t.rows[198][5].empty());  // a training drop of that condition, better
}

TEST_F(DiagnosePlots, TheGapFigureDrawsEachPanelInItsLayout) {
  const std::optional<GapLayout> vacuum = WriteGapPanelData(Rows(12, 4), "vacuum", dir_);
  const std::optional<GapLayout> air = WriteGapPanelData(Rows(100, 2), "air", dir_);
  const std::string gp = GapPerDropFigure("base + rate_damping", {vacuum, air}, true);
  const size_t at = gp.find("data/gap_air.csv");
  const std::string air_panel = gp.substr(at, gp.find("unset multiplot", at) - at);
  EXPECT_EQ(Count(gp, "with vectors heads"), 2u * 2u);  // whiskers of base and effect, in the PNG and the SVG
  EXPECT_EQ(air_panel.find("xtic("), std::string::npos);  // no tic per drop past the threshold
  EXPECT_NE(air_panel.find("with labels"), std::string::npos);
  Render(gp, "plots/gap_per_drop.png");
}

TEST_F(DiagnosePlots, BandsArePercentilesOfTheSamplesInEachTimeBin) {
  // 4 bins over 0..0.04 s (its ends set by one sample each); in each, residuals 0, 1, ..., 100
  // (base) and their negatives (effect): linear interpolation between order statistics puts the
  // 5th, 50th and 95th percentiles at 5, 50 and 95.
  std::vector<ResidualSample> samples{{0.0, 50.0, -50.0}, {0.04, 50.0, -50.0}};
  for (int b = 0; b < 4; ++b)
    for (int v = 100; v >= 0; --v) samples.push_back({0.01 * b + 0.001 + 0.0001 * (v % 50), double(v), -double(v)});
  const std::vector<ResidualBand> bands = ResidualBands(samples, 4);
  ASSERT_EQ(bands.size(), 4u);
  for (int b = 0; b < 4; ++b) {
    EXPECT_NEAR(bands[b].t_ms, 5.0 + 10.0 * b, 1e-12);
    const size_t n = bands[b].samples;
    EXPECT_EQ(n, b == 0 || b == 3 ? 102u : 101u);
    if (b == 0 || b == 3) continue;
    EXPECT_DOUBLE_EQ(bands[b].base[0], 5.0);
    EXPECT_DOUBLE_EQ(bands[b].base[1], 50.0);
    EXPECT_DOUBLE_EQ(bands[b].base[2], 95.0);
    EXPECT_DOUBLE_EQ(bands[b].augmented[0], -95.0);
    EXPECT_DOUBLE_EQ(bands[b].augmented[2], -5.0);
  }
  // A bin of fewer than five samples says nothing: left out.
  EXPECT_TRUE(ResidualBands({{0, 1, 1}, {1, 1, 1}}, 2).empty());
}

TEST_F(DiagnosePlots, PastTenHeldOutDropsTheResidualsAreBandsOnOneScale) {
  std::vector<ResidualSample> samples;
  for (int i = 0; i < 3000; ++i) samples.push_back({1e-5 * i, std::sin(i * 0.01), 0.1 * std::sin(i * 0.01)});
  WriteResidualBands(ResidualBands(samples), "vacuum", dir_);
  io::WriteFileAtomically((dir_ / "data/residuals_held_out.csv").string(), [](std::ostream& out) {
    out << "t_s,residual_base,residual_augmented,atmosphere\n0,0.1,0.01,air\n0.01,-0.2,0.02,air\n";
  });
  ResidualPanels panels;
  panels.layout = {ResidualLayout::kBands, ResidualLayout::kSamples};
  panels.drops = {32, 4};
  panels.t_lo_ms = 0, panels.t_hi_ms = 30, panels.r_lo = -1, panels.r_hi = 1;
  const std::string gp = ResidualFigure("base + rate_damping", panels);
  EXPECT_EQ(Count(gp, "with filledcurves"), 2u * 2u);  // vacuum: base and effect; PNG and SVG
  EXPECT_EQ(Count(gp, "residuals_held_out.csv"), 2u * 2u);  // air: every sample
  EXPECT_NE(gp.find("set yrange [-1.10"), std::string::npos);  // 5 % and 0.001 past the bands' extremes
  EXPECT_NE(gp.find("(32 held-out drops, binned)"), std::string::npos);
  Render(gp, "plots/residuals.png");
}

}  // namespace
}  // namespace touchdown::gap
