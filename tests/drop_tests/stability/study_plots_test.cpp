// The study's figures at the size studies are run: a synthetic 20,000-landing table (records made
// from the plan's own draws, tipped over with a known probability over the map), drawn by the
// study's plot writer. Checked in the gnuplot script and data files it writes: the map's colour
// scale fits the cells (linear to a round number above the highest, logarithmic where P spans
// decades), the study file's contour levels are drawn, landings are drawn one by one only up to
// the threshold; the exceedance of pad penetration leaves lifted pads out, on an axis from 0 to a
// little past the deepest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/stability/study_summary.h"
#include "drop_tests/util/splitmix.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {

namespace fs = std::filesystem;

// A study over the lunar study's map (slope 0-20 deg x horizontal speed 0-1 m/s, 10 x 10 cells);
// `map_extra` adds keys to its map block.
std::string StudyText(const std::string& map_extra = "") {
  // Appended piece by piece: GCC 12 warns (-Warray-bounds, falsely) on a chain of + over the macro.
  std::string text = "schema_version: 1\ntype: stability\nname: synthetic\nlander: {scenario: ";
  text += TOUCHDOWN_SOURCE_DIR;
  text += "/data/scenarios/lander_case_A.yaml}\n"
          "random: {samples: 10, seed: 4, slope_deg: {uniform: [0, 20]}, horizontal_speed_m_s: {uniform: [0, 1]}}\n"
          "study: {map: {x: slope_deg, y: horizontal_speed_m_s, bins: [10, 10]";
  text += map_extra;
  text += "}, recheck: none, joint_range_sensitivity: none}\n";
  return text;
}

// A uniform number in [0, 1) fixed by the landing's index: the same table on every run.
double Uniform(int64_t index) { return static_cast<double>(io::SplitMix64(static_cast<uint64_t>(index)) >> 11) * 0x1p-53; }

// One record per landing of the study: tipped over with probability `p(slope_deg, speed_m_s)` of its
// drawn map coordinates; pad 1 lifted (-0.4 m) in every fifth landing, the others loaded 10-110 mm.
std::vector<sweep::DropRecord> Records(const Study& study, const std::function<double(double, double)>& p) {
  std::vector<sweep::DropRecord> records;
  for (int64_t i = 0; i < study.plan.size(); ++i) {
    sweep::DropRecord r;
    r.index = i;
    r.kind = sweep::DropKind::kLander;
    r.ok = true;
    const double x = MapCoordinate(study, study.map->x, i), y = MapCoordinate(study, study.map->y, i);
    r.tipped_over = Uniform(i) < p(x, y) ? 1.0 : 0.0;
    r.max_tilt_deg = 2.0 + x;
    r.final_tilt_deg = 0.5 * x;
    const double depth_m = 0.01 + 0.1 * Uniform(i + 1000003);
    r.pad_final_penetration_m = {i % 5 == 0 ? -0.4 : depth_m, depth_m, 0.8 * depth_m, 0.9 * depth_m};
    r.final_penetration_m = depth_m;
    r.peak_leg_force_N = 1000.0 * depth_m;
    r.time_to_rest_s = 1.0;
    records.push_back(r);
  }
  return records;
}

struct Drawn {
  StudySummary summary;
  std::string script;
  fs::path dir;
};

struct StudyPlotsTest : testing_scratch::ScratchDirTest {
  // The study of `samples` landings drawn with tip-over probability `p` into plots of their own.
  Drawn Draw(int64_t samples, const std::function<double(double, double)>& p, const std::string& map_extra = "") {
    const Study study = LoadStudy(Write("study.yaml", StudyText(map_extra)), "", samples);
    const std::vector<sweep::DropRecord> records = Records(study, p);
    Drawn d{Summarise(study, records), "", fs::path(Path("out_" + std::to_string(++draws_)))};
    WriteStudyPlots(study, d.summary, records, d.dir.string());
    d.script = Slurp(d.dir / "plots" / "study.gp");
    return d;
  }
  int draws_ = 0;
};

double HighestCell(const StudySummary& s) {
  double highest = 0.0;
  for (const MapCell& c : s.map)
    if (c.landings > 0) highest = std::max(highest, c.probability);
  return highest;
}

// The map figure's part of the script (up to the exceedance figure's).
std::string MapScript(const std::string& script) {
  return script.substr(0, script.find("plots/exceedance.png"));
}

TEST_F(StudyPlotsTest, TwentyThousandLandingsMapOnALinearScaleFittedToTheCells) {
  // P up to about 0.2 at the far corner (the shipped lunar study's highest cells).
  const Drawn d = Draw(20000, [](double slope, double speed) { return 0.2 * slope / 20.0 * speed; });
  ASSERT_EQ(d.summary.landings, 20000);
  ASSERT_GT(d.summary.tipped, kDefaultMaxDrawnLandings);  // too many crosses to draw one by one
  const std::string map = MapScript(d.script);
  const double highest = HighestCell(d.summary);
  ASSERT_GT(highest, 0.12);
  ASSERT_LT(highest, 0.3);
  // Linear, from 0 to a round number at or above the highest cell (1, 1.5, 2, 2.5, 3, 4, 5, 6, 8
  // times a power of ten: at most a third above it), not 1.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(map, m, std::regex(R"(unset logscale cb\nset format cb '% h'\nset cbrange \[0:([0-9.e+-]+)\])")))
      << map;
  const double top = std::stod(m[1]);
  EXPECT_GE(top, highest);
  EXPECT_LE(top, highest * 4.0 / 3.0);
  // The default contours, 0.01 and 0.1, both crossed by this map, each drawn from its data file.
  for (const char* level : {"1", "2"}) {
    const std::string file = std::string("plots/data/map_contour_") + level + ".csv";
    EXPECT_TRUE(fs::is_regular_file(d.dir / file)) << file;
    EXPECT_NE(map.find("'" + file + "' using 1:2 with lines lw"), std::string::npos) << file;
  }
  EXPECT_NE(map.find("title 'P = 0.01 contour'"), std::string::npos);
  EXPECT_NE(map.find("title 'P = 0.1 contour'"), std::string::npos);
  // Past the threshold no landing is drawn one by one, and the figure says so.
  EXPECT_EQ(map.find("map_landed"), std::string::npos);
  EXPECT_EQ(map.find("map_tipped"), std::string::npos);
  EXPECT_FALSE(fs::exists(d.dir / "plots/data/map_landed.csv"));
  EXPECT_FALSE(fs::exists(d.dir / "plots/data/map_tipped.csv"));
  EXPECT_NE(map.find("drawn when at most 500"), std::string::npos);
  // Every cell holds about 200 landings: none too thin to read (the interval panel's hatching).
  EXPECT_FALSE(fs::exists(d.dir / "plots/data/map_unreadable_cells.csv"));
  EXPECT_TRUE(fs::is_regular_file(d.dir / "plots/tip_over_map.png"));
}

TEST_F(StudyPlotsTest, ProbabilitiesSpanningDecadesGetALogScaleAndZeroCellsApart) {
  // P from 1e-4 at slope 0 to 1 from 17.8 deg on: the low cells hold no tip-over, the lowest with
  // one hold 1 in about 200 (0.005), more than two decades below the highest.
  const Drawn d = Draw(20000, [](double slope, double) { return std::pow(10.0, -4.0 + 4.5 * slope / 20.0); },
                       ", contours: [0.003, 0.03, 0.3]");
  const std::string map = MapScript(d.script);
  EXPECT_NE(map.find("set logscale cb\nset cbrange [0.001:1]\n"), std::string::npos) << map;
  EXPECT_TRUE(fs::is_regular_file(d.dir / "plots/data/map_zero_cells.csv"));
  EXPECT_NE(map.find("title 'no tip-over in the cell (P = 0)'"), std::string::npos);
  // The study file's three levels, in their order.
  const size_t a = map.find("'P = 0.003"), b = map.find("'P = 0.03"), c = map.find("'P = 0.3");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(c, std::string::npos);
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_EQ(map.find("map_landed"), std::string::npos);
}

TEST_F(StudyPlotsTest, LandingsAreDrawnOneByOneUpToTheThreshold) {
  const auto p = [](double slope, double speed) { return 0.2 * slope / 20.0 * speed; };
  const Drawn few = Draw(400, p);
  ASSERT_LE(few.summary.landings, kDefaultMaxDrawnLandings);
  const std::string map = MapScript(few.script);
  EXPECT_NE(map.find("'plots/data/map_landed.csv' using 1:2 with points"), std::string::npos) << map;
  EXPECT_NE(map.find("'plots/data/map_tipped.csv' using 1:2 with points"), std::string::npos) << map;
  EXPECT_NE(map.find("every landing drawn"), std::string::npos);
  // 400 landings in 100 cells: many cells too thin to read, hatched.
  EXPECT_TRUE(fs::is_regular_file(few.dir / "plots/data/map_unreadable_cells.csv"));
  // A study file's own threshold: 100 keeps the 400 circles off, the tip-overs (fewer) on.
  const Drawn capped = Draw(400, p, ", max_drawn_landings: 100");
  ASSERT_LE(capped.summary.tipped, 100);
  const std::string capped_map = MapScript(capped.script);
  EXPECT_EQ(capped_map.find("map_landed"), std::string::npos);
  EXPECT_NE(capped_map.find("map_tipped"), std::string::npos);
}

TEST_F(StudyPlotsTest, PadPenetrationExceedanceLeavesLiftedPadsOut) {
  const Drawn d = Draw(20000, [](double, double) { return 0.0; });
  // Pad 1 lifted in every fifth landing: its curve starts above 0 and its key counts them.
  const std::string pad1 = Slurp(d.dir / "plots/data/exceedance_pad1.csv");
  EXPECT_GT(std::stod(pad1.substr(0, pad1.find(','))), 0.0);
  EXPECT_NE(d.script.find("pad 1: 16000 loaded, 4000 lifted"), std::string::npos);
  EXPECT_NE(d.script.find("counted apart: 4000 of 80000"), std::string::npos);
  // The depth axis from 0 to a little past the deepest pad (110 mm at most).
  std::smatch m;
  const std::string exceedance = d.script.substr(d.script.find("plots/exceedance.png"));
  ASSERT_TRUE(std::regex_search(exceedance, m, std::regex(R"(loaded pad \[mm\]'\n.*\nset xrange \[0:([0-9.]+)\])")))
      << exceedance;
  EXPECT_GT(std::stod(m[1]), 100.0);
  EXPECT_LE(std::stod(m[1]), 120.0);
  // No tip-over at all: a linear scale over [0, 1] and the contours named as not crossed.
  EXPECT_NE(MapScript(d.script).find("set cbrange [0:1]"), std::string::npos);
  EXPECT_NE(MapScript(d.script).find("'P = 0.1: not crossed'"), std::string::npos);
}

TEST_F(StudyPlotsTest, BadContourLevelsAndThresholdsNameTheirField) {
  const auto expect_error = [&](const std::string& extra, const std::string& field, const std::string& reason) {
    try {
      LoadStudy(Write("bad.yaml", StudyText(extra)));
      ADD_FAILURE() << "accepted: " << extra;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  };
  expect_error(", contours: [0.1, 0.01]", "study.map.contours[1]", "increase");
  expect_error(", contours: [0.1, 0.1]", "study.map.contours[1]", "increase");
  expect_error(", contours: [0.5, 1]", "study.map.contours[1]", "below 1");
  expect_error(", contours: [0, 0.5]", "study.map.contours[0]", "positive");
  expect_error(", contours: [0.01, 0.02, 0.05, 0.1, 0.2, 0.5]", "study.map.contours", "at most 5");
  expect_error(", contours: []", "study.map.contours", "empty");
  expect_error(", max_drawn_landings: 2.5", "study.map.max_drawn_landings", "whole number");
  expect_error(", max_drawn_landings: -1", "study.map.max_drawn_landings", "");
  // A single level, and the defaults.
  EXPECT_EQ(LoadStudy(Write("one.yaml", StudyText(", contours: 0.5"))).map->contours, std::vector<double>{0.5});
  const Study defaults = LoadStudy(Write("defaults.yaml", StudyText()));
  EXPECT_EQ(defaults.map->contours, (std::vector<double>{0.01, 0.1}));
  EXPECT_EQ(defaults.map->max_drawn_landings, 500);
  // summary.json records both with the map's other keys.
  const nlohmann::json map = SummaryJson(defaults, Summarise(defaults, {}))["map"];
  EXPECT_EQ(map["contours"], nlohmann::json({0.01, 0.1}));
  EXPECT_EQ(map["max_drawn_landings"], 500);
}

}  // namespace
}  // namespace touchdown::stability
