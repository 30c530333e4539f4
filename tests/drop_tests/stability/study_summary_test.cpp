// The summary of hand-made landing records whose answers are known: counts, the tip-over
// probability and its interval, percentiles over the landings that stayed up, the map's cells,
// the worst cases with their conditions and the caps; and the files the analysis writes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/stability/study_summary.h"
#include "drop_tests/sweep/sweep.h"
#include "rft/input_error.h"
#include "tests/drop_tests/stability/study_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {

std::string SummaryStudyText(const std::string& extra = "") {
  return std::string("schema_version: 1\ntype: stability\nname: hand_made\nlander: {scenario: ") +
         TOUCHDOWN_SOURCE_DIR +
         "/data/scenarios/lander_case_A.yaml}\n"
         "random: {samples: 10, seed: 4, slope_deg: {uniform: [0, 20]}, horizontal_speed_m_s: {uniform: [0, 1]}}\n"
         "study: {map: {x: slope_deg, y: horizontal_speed_m_s, bins: [2, 4]}, worst_cases: 3, max_tip_over_cases: 2}\n" +
         extra;
}

// Ten landings: 3, 6 and 9 tipped over; max tilt 1..10 deg by index, final tilt a tenth of it;
// a pad's largest swing on its joint 20 deg times the index (past 90 deg from index 5 on); drop 7
// failed (not counted).
std::vector<sweep::DropRecord> HandMadeRecords() {
  std::vector<sweep::DropRecord> records;
  for (int i = 0; i < 10; ++i) {
    sweep::DropRecord r;
    r.index = i;
    r.drop_id = sweep::SweepPlan{}.DropId(i);  // "d" and the index
    r.kind = sweep::DropKind::kLander;
    r.ok = i != 7;
    r.failure = r.ok ? "" : "made up";
    r.tipped_over = r.ok ? (i % 3 == 0 && i > 0 ? 1.0 : 0.0) : std::nan("");
    r.max_tilt_deg = i + 1.0;
    r.final_tilt_deg = 0.1 * (i + 1.0);
    r.max_joint_swing_deg = 20.0 * i;
    r.final_penetration_m = 0.01 * i;
    r.pad_final_penetration_m = {0.01 * i, 0.0, 0.0, 0.0};
    r.time_to_rest_s = i == 5 ? std::nan("") : 0.5;  // drop 5: still moving at the end
    r.slope_deg = 2.0 * i;
    records.push_back(r);
  }
  return records;
}

struct StudySummaryTest : testing_scratch::ScratchDirTest {};

// A lander file's leg load limit: landings whose peak leg load passed it are counted, alone and with
// the tip-overs, each with its exact interval; without a limit the summary has no such entry.
TEST_F(StudySummaryTest, LegLoadLimitCountsLandingsOverItAndTheirUnionWithTipOvers) {
  Study study = LoadStudy(Write("study.yaml", SummaryStudyText()));
  std::vector<sweep::DropRecord> records = HandMadeRecords();
  for (sweep::DropRecord& r : records) r.peak_leg_force_N = 100.0 * r.index;  // over 450 N: 5, 6, 8, 9 (7 failed)
  EXPECT_FALSE(Summarise(study, records).leg_load_limit.has_value());
  EXPECT_FALSE(SummaryJson(study, Summarise(study, records)).contains("leg_load_limit"));
  for (scenario::LanderLegSpec& leg : study.plan.lander->lander.legs) leg.load_limit_N = 450.0;
  const StudySummary s = Summarise(study, records);
  ASSERT_TRUE(s.leg_load_limit.has_value());
  EXPECT_EQ(s.leg_load_limit->over_limit, 4);
  EXPECT_EQ(s.leg_load_limit->tipped_or_over_limit, 5);  // tipped 3, 6, 9: adds 3
  const BinomialInterval over = ClopperPearson(4, 9), either = ClopperPearson(5, 9);
  const nlohmann::json j = SummaryJson(study, s)["leg_load_limit"];
  EXPECT_EQ(j["load_limit_N"].get<double>(), 450.0);
  EXPECT_EQ(j["landings_over_limit"].get<int64_t>(), 4);
  EXPECT_DOUBLE_EQ(j["over_limit_probability"].get<double>(), 4.0 / 9.0);
  EXPECT_EQ(j["over_limit_probability_interval_95"][0].get<double>(), over.low);
  EXPECT_EQ(j["over_limit_probability_interval_95"][1].get<double>(), over.high);
  EXPECT_DOUBLE_EQ(j["tipped_or_over_limit_probability"].get<double>(), 5.0 / 9.0);
  EXPECT_EQ(j["tipped_or_over_limit_probability_interval_95"][0].get<double>(), either.low);
  EXPECT_EQ(j["tipped_or_over_limit_probability_interval_95"][1].get<double>(), either.high);
}

TEST_F(StudySummaryTest, CountsProbabilityAndPercentilesOfHandMadeRecords) {
  const Study study = LoadStudy(Write("study.yaml", SummaryStudyText()));
  const StudySummary s = Summarise(study, HandMadeRecords());
  EXPECT_EQ(s.planned, 10);
  EXPECT_EQ(s.landings, 9);
  EXPECT_EQ(s.failed, 1);
  EXPECT_EQ(s.tipped, 3);
  EXPECT_EQ(s.unsettled, 1);
  // Swung past edge-on: 5, 6, 8 and 9 (7 failed); of the tip-overs 6 and 9.
  EXPECT_EQ(s.swung_past_edge_on, 4);
  EXPECT_EQ(s.tipped_swung_past_edge_on, 2);
  EXPECT_DOUBLE_EQ(s.tip_over_probability, 3.0 / 9.0);
  const BinomialInterval expected = ClopperPearson(3, 9);
  EXPECT_EQ(s.interval.low, expected.low);
  EXPECT_EQ(s.interval.high, expected.high);
  // Stayed up: indices 0, 1, 2, 4, 5, 8 -> max tilt 1, 2, 3, 5, 6, 9 deg.
  const MetricPercentiles& tilt = s.metrics.at(0);
  ASSERT_STREQ(tilt.metric->name, "max_tilt_deg");
  EXPECT_EQ(tilt.count, 6);
  EXPECT_DOUBLE_EQ(tilt.p50, 4.0);           // h = 2.5: 3 + 0.5 (5 - 3)
  EXPECT_DOUBLE_EQ(tilt.p95, 6.0 + 0.75 * 3.0);  // h = 4.75
  EXPECT_DOUBLE_EQ(tilt.max, 9.0);
  // Worst cases: the three largest max tilts among those that stayed up; tip-overs capped at 2.
  ASSERT_EQ(s.worst_tilt.size(), 3u);
  EXPECT_EQ(s.worst_tilt[0].index, 8);
  EXPECT_EQ(s.worst_tilt[1].index, 5);
  EXPECT_EQ(s.worst_tilt[2].index, 4);
  ASSERT_EQ(s.tip_overs.size(), 2u);
  EXPECT_EQ(s.tip_overs[0].index, 3);
  EXPECT_EQ(s.tip_overs[1].index, 6);
  // The map: 2 x 4 cells over the plan's ranges; each landing in the cell of its drawn parameters.
  ASSERT_EQ(s.map.size(), 8u);
  int64_t landings = 0, tipped = 0;
  for (const MapCell& c : s.map) landings += c.landings, tipped += c.tipped;
  EXPECT_EQ(landings, 9);
  EXPECT_EQ(tipped, 3);
  for (const sweep::DropRecord& r : HandMadeRecords()) {
    if (!r.ok) continue;
    const sweep::SweepDropParams p = study.plan.DropAt(r.index);
    const int ix = static_cast<int>(p.slope_rad * 180.0 / M_PI / 10.0);
    const int iy = static_cast<int>(p.horizontal_speed_m_s / 0.25);
    const MapCell& c = s.map.at(static_cast<size_t>(ix) * 4 + iy);
    EXPECT_LE(c.x_low, p.slope_rad * 180.0 / M_PI + 1e-12);
    EXPECT_GE(c.x_high, p.slope_rad * 180.0 / M_PI - 1e-12);
    EXPECT_GE(c.landings, 1);
  }
  const nlohmann::json j = SummaryJson(study, s);
  EXPECT_EQ(j["landings"], 9);
  EXPECT_EQ(j["tip_over_probability_interval_95"][0].get<double>(), expected.low);
  EXPECT_EQ(j["percentiles"]["max_tilt_deg"]["p50"].get<double>(), 4.0);
  // No stroke recorded: no percentile keys (never null), the count and a reason.
  EXPECT_FALSE(j["percentiles"]["max_absorber_stroke_m"].contains("p50"));
  EXPECT_EQ(j["percentiles"]["max_absorber_stroke_m"]["landings"], 0);
  EXPECT_TRUE(j["percentiles"]["max_absorber_stroke_m"]["reason"].is_string());
  EXPECT_EQ(j["tip_overs"].size(), 2u);
  EXPECT_EQ(j["worst_max_tilt"][0]["conditions"]["slope_deg"].get<double>(), 16.0);
  EXPECT_EQ(j["samples_overridden"], false);
  EXPECT_EQ(j["landings_swung_past_edge_on"], 4);
  EXPECT_EQ(j["tip_overs_swung_past_edge_on"], 2);
  // Over the landings that stayed up (0, 1, 2, 4, 5, 8): 0 ... 160 deg.
  EXPECT_EQ(j["percentiles"]["max_joint_swing_deg"]["max"].get<double>(), 160.0);
}

TEST_F(StudySummaryTest, AnalysisWritesItsTablesAndPlotsFromTheDatabase) {
  // Hand-made records: no follow-up (they would simulate the landings the records only pretend).
  std::string text = SummaryStudyText();
  text.replace(text.find("max_tip_over_cases: 2}"), 22,
               "max_tip_over_cases: 2, recheck: none, joint_range_sensitivity: none}");
  const Study study = LoadStudy(Write("study.yaml", text));
  const std::string out = Path("out");
  std::filesystem::create_directories(out);
  {
    sweep::ResultsDb db(sweep::ResultsDbPath(out));
    db.SetMeta({{"plan_digest", sweep::PlanDigest(study.plan)}});
    std::vector<sweep::DropRecord> records = HandMadeRecords();
    records.pop_back();  // one landing missing: refused, naming the database
    db.Insert(records);
  }
  try {
    test::AnalyseStudy(study, out);
    ADD_FAILURE() << "an incomplete study was analysed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1 of 10 landings missing"), std::string::npos) << e.what();
  }
  sweep::ResultsDb(sweep::ResultsDbPath(out)).Insert({HandMadeRecords().back()});
  const StudySummary s = test::AnalyseStudy(study, out);
  EXPECT_EQ(s.landings, 9);
  for (const char* file : {"summary.json", "percentiles.csv", "tip_over_map.csv", "plots/tip_over_map.png",
                           "plots/tip_over_map.svg", "plots/exceedance.png", "plots/exceedance.svg",
                           "plots/histograms.png", "plots/histograms.svg"})
    EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::path(out) / file)) << file;
  const std::string map = Slurp(std::filesystem::path(out) / "tip_over_map.csv");
  EXPECT_EQ(map.substr(0, map.find('\n')),
            "slope_deg_low,slope_deg_high,horizontal_speed_m_s_low,horizontal_speed_m_s_high,landings,tipped_over,"
            "tip_over_probability,interval_95_low,interval_95_high");
  EXPECT_EQ(std::count(map.begin(), map.end(), '\n'), 9);  // header and 8 cells
  const std::string percentiles = Slurp(std::filesystem::path(out) / "percentiles.csv");
  EXPECT_NE(percentiles.find("\nmax_tilt_deg,deg,6,4,8.25,8.85"), std::string::npos) << percentiles;  // p99 8.85 (+1 ulp)
  // The follow-ups turned off, and summary.json says so.
  const nlohmann::json j = nlohmann::json::parse(Slurp(std::filesystem::path(out) / "summary.json"));
  EXPECT_EQ(j["recheck"]["enabled"], false);
  EXPECT_EQ(j["joint_range_sensitivity"]["ran"], false);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(out) / "recheck"));
  // Another study (here: other samples) in the same database is refused.
  const Study other = LoadStudy(Path("study.yaml"), "", 12);
  EXPECT_THROW(test::AnalyseStudy(other, out), InputError);
}

TEST_F(StudySummaryTest, BadStudyBlocksNameFileAndField) {
  auto expect_error = [&](const std::string& text, const std::string& field, const std::string& reason,
                          std::optional<int64_t> samples = std::nullopt) {
    const std::string file = Write("bad.yaml", text);
    try {
      LoadStudy(file, "", samples);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(field), std::string::npos) << what;
      EXPECT_NE(what.find(reason), std::string::npos) << what;
    }
  };
  const std::string head = std::string("schema_version: 1\ntype: stability\nlander: {scenario: ") + TOUCHDOWN_SOURCE_DIR +
                           "/data/scenarios/lander_case_A.yaml}\ngrid: {slope_deg: [0, 5]}\n";
  expect_error(head + "study: {map: {x: slope_deg, y: roll_deg}}\n", "study.map.y", "does not vary");
  expect_error(head + "study: {map: {x: slope_deg, y: pad_soils}}\n", "study.map.y", "number parameter");
  expect_error(head + "study: {map: {x: slope_deg, y: slope_deg}}\n", "study.map", "");
  expect_error(head + "study: {map: {x: slope_deg, y: roll_deg, bins: [1, 4]}}\n", "study.map.bins[0]", "from 2");
  expect_error(head + "study: {worst_cases: -1}\n", "study.worst_cases", "");
  expect_error(head + "study: {colour: red}\n", "study.colour", "");
  // The follow-ups' settings (lander_case_A runs at rtol 1e-7).
  expect_error(head + "study: {recheck: {rtol: 1e-7}}\n", "study.recheck.rtol",
               "below the study scenario's rtol 1e-07");
  expect_error(head + "study: {recheck: {rtol: 0}}\n", "study.recheck.rtol", "above 0");
  expect_error(head + "study: {recheck: {tilt_margin_deg: 91}}\n", "study.recheck.tilt_margin_deg", "from 0 to 90");
  expect_error(head + "study: {recheck: {tilt_margin_deg: -1}}\n", "study.recheck.tilt_margin_deg", "from 0 to 90");
  expect_error(head + "study: {recheck: {unsettled: 2}}\n", "study.recheck.unsettled", "");
  expect_error(head + "study: {recheck: {rtol: 1e-9, margin: 2}}\n", "study.recheck.margin", "");
  expect_error(head + "study: {recheck: sometimes}\n", "study.recheck", "none or a mapping");
  expect_error(head + "study: {joint_range_sensitivity: {samples: 0}}\n", "study.joint_range_sensitivity.samples", "");
  expect_error(head + "study: {joint_range_sensitivity: {samples: 2.5}}\n", "study.joint_range_sensitivity.samples",
               "whole number");
  expect_error(head + "study: {joint_range_sensitivity: {factor: 2}}\n", "study.joint_range_sensitivity.factor", "");
  expect_error(head + "study: {joint_range_sensitivity: {screen_margin_deg: -1}}\n",
               "study.joint_range_sensitivity.screen_margin_deg", "none or from 0 to 90");
  expect_error(head + "study: {joint_range_sensitivity: {screen_margin_deg: some}}\n",
               "study.joint_range_sensitivity.screen_margin_deg", "");
  expect_error(head + "study: {joint_range_sensitivity: always}\n", "study.joint_range_sensitivity",
               "none or a mapping {samples, screen_margin_deg}");
  expect_error(head, "--samples", "no random block", 5);
  expect_error("schema_version: 1\ntype: stability\ngrid: {slope_deg: [0, 5]}\n", "lander", "missing");
  // A plain sweep file is no study.
  expect_error(std::string("schema_version: 1\ntype: sweep\nlander: {scenario: ") + TOUCHDOWN_SOURCE_DIR +
                   "/data/scenarios/lander_case_A.yaml}\ngrid: {slope_deg: [0, 5]}\n",
               "type", "stability");
}

// A tip-over's edge, its pads' soils and the direction it fell, relative to downhill and to the
// landing's horizontal velocity (wrapped to (-180, 180]); a landing that stayed up lists none, and
// an edge number that no lander has (a database from elsewhere) lists none rather than a wrong pad.
TEST(StudyLandingJson, ATipOverNamesItsEdgeAndWhereItFell) {
  sweep::DropRecord r;
  r.kind = sweep::DropKind::kLander;
  r.ok = true;
  r.tipped_over = 1.0;
  r.pad_soil = {"fjs1_lp", "fjs1_cp", "fjs1_cp", "fjs1_lp"};
  r.slope_deg = 15.0;
  r.downhill_azimuth_deg = 170.0;
  r.horizontal_speed_m_s = 0.5;
  r.horizontal_azimuth_deg = -100.0;
  r.tip_over_edge = 4.0;  // pads 4 and 1
  r.tip_over_azimuth_deg = -175.0;
  const nlohmann::json j = LandingJson(r);
  ASSERT_TRUE(j.contains("tip_over"));
  const nlohmann::json& t = j["tip_over"];
  EXPECT_EQ(t["edge_pads"], nlohmann::json({4, 1}));
  EXPECT_EQ(t["edge_pad_soils"], nlohmann::json({"fjs1_lp", "fjs1_lp"}));
  EXPECT_DOUBLE_EQ(t["fell_towards_azimuth_deg"].get<double>(), -175.0);
  EXPECT_NEAR(t["fell_from_downhill_deg"].get<double>(), 15.0, 1e-12);  // across the +-180 seam
  EXPECT_NEAR(t["fell_from_horizontal_velocity_deg"].get<double>(), -75.0, 1e-12);
  r.tip_over_azimuth_deg = -10.0;  // exactly uphill of 170: +180, never -180
  EXPECT_EQ(LandingJson(r)["tip_over"]["fell_from_downhill_deg"].get<double>(), 180.0);
  r.slope_deg = 0.0;  // level ground: no downhill to measure from
  EXPECT_FALSE(LandingJson(r)["tip_over"].contains("fell_from_downhill_deg"));
  for (double bad : {0.0, 5.0, 2.5, std::nan("")}) {
    r.tip_over_edge = bad;
    EXPECT_FALSE(LandingJson(r).contains("tip_over")) << bad;
  }
}

}  // namespace
}  // namespace touchdown::stability
