// What the lander's summary says of its gear. Crushable leg absorbers on the paper's case A (every
// leg alike): a honeycomb core strokes only in compression, only at its crush force, and what it
// crushed stays crushed; the summary reads per leg the peak load, the stroke used and the stroke
// left, as an inspection after the landing does. And the support polygon's edges at the end: each
// edge's static tip-over angle against the closed form of a level, symmetric stance.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "drop_tests/scenario/lander_leg_load.h"
#include "drop_tests/scenario/lander_outputs.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "rft/units.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::scenario {
namespace {

constexpr double kCrushForceN = 40.0;   // below the rigid legs' 86-133 N peaks, above a quarter of the 42 N weight
constexpr double kStrokeLimitM = 0.05;  // more than the landing uses: the core never bottoms out
constexpr double kDriftM = 1e-12;       // a locked stroke's drift, far below the 10 mm crushed

LanderRun CrushableCaseA() {
  LanderScenario scenario = test::CoarseScenario("lander_case_A");
  lander::ShockAbsorber core;
  core.kind = lander::ShockAbsorber::Kind::kCrushable;
  core.crush_force_N = kCrushForceN;
  core.stroke_limit_m = kStrokeLimitM;
  for (LanderLegSpec& leg : scenario.lander.legs) leg.absorber = core;
  return RunLanderScenario(scenario);
}

TEST(LanderCrushable, CoresStrokeOnlyForwardAndOnlyAtTheirCrushForce) {
  const LanderRun run = CrushableCaseA();
  const auto& trace = run.result.trace;
  ASSERT_GT(trace.size(), 10u);
  for (int leg = 0; leg < lander::kNumLegs; ++leg) {
    double crushed = 0.0;
    for (size_t k = 0; k < trace.size(); ++k) {
      const double s = trace[k].stroke_m[leg], f = trace[k].leg_force_N[leg];
      // Rigid below the crush force, crushing at it: the force never passes it.
      EXPECT_LE(f, kCrushForceN * (1 + 1e-9)) << "leg " << leg + 1 << " at " << trace[k].t_s << " s";
      if (k > 0) {
        // Locked, the stroke is a constraint held to the integration's drift (1e-19 m seen).
        EXPECT_GE(s, trace[k - 1].stroke_m[leg] - kDriftM) << "leg " << leg + 1 << ": a crushed core does not recover";
      }
      crushed = std::max(crushed, s);
    }
    EXPECT_GT(crushed, 1e-4) << "leg " << leg + 1 << " crushed: the rigid legs' peak is twice the crush force";
    EXPECT_LT(crushed, kStrokeLimitM);
    EXPECT_NEAR(trace.back().stroke_m[leg], crushed, kDriftM) << "the stroke at the end is the most it crushed";
  }
}

TEST(LanderCrushable, SummaryReadsEachLegsPeakLoadStrokeUsedAndStrokeLeft) {
  const LanderRun run = CrushableCaseA();
  const std::array<LegLoadSummary, lander::kNumLegs> legs = LegLoadSummaries(run.scenario.lander, run.result.trace);
  const nlohmann::json summary = LanderSummaryJson(run);
  ASSERT_EQ(summary["legs"].size(), static_cast<size_t>(lander::kNumLegs));
  for (int i = 0; i < lander::kNumLegs; ++i) {
    double peak = 0.0, stroke = 0.0;
    for (const lander::LanderSample& s : run.result.trace)
      peak = std::max(peak, s.leg_force_N[i]), stroke = std::max(stroke, s.stroke_m[i]);
    EXPECT_EQ(legs[i].peak_axial_force_N, peak);
    // The core held the load at its crush force while it crushed: the peak is that force.
    EXPECT_NEAR(peak, kCrushForceN, 1e-9 * kCrushForceN);
    ASSERT_TRUE(legs[i].max_stroke_m && legs[i].stroke_left_m);
    EXPECT_EQ(*legs[i].max_stroke_m, stroke);
    EXPECT_EQ(*legs[i].stroke_left_m, kStrokeLimitM - stroke);
    const nlohmann::json& leg = summary["legs"][i];
    EXPECT_EQ(leg["pad"], i + 1);
    EXPECT_EQ(leg["peak_axial_force_N"].get<double>(), peak);
    EXPECT_EQ(leg["max_stroke_m"].get<double>(), stroke);
    EXPECT_EQ(leg["stroke_left_m"].get<double>(), kStrokeLimitM - stroke);
  }
}

TEST(LanderCrushable, RigidLegsReportTheirLoadAndNoStroke) {
  const LanderRun run = RunLanderScenario(test::CoarseScenario("lander_case_A"));
  const nlohmann::json summary = LanderSummaryJson(run);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const nlohmann::json& leg = summary["legs"][i];
    double peak = 0.0;
    for (const lander::LanderSample& s : run.result.trace) peak = std::max(peak, LegAxialForce(run.scenario.lander, s, i));
    EXPECT_EQ(leg["peak_axial_force_N"].get<double>(), peak);
    EXPECT_GT(peak, 2 * kCrushForceN) << "what the crushable test's force is set below";
    EXPECT_FALSE(leg.contains("max_stroke_m"));
    EXPECT_FALSE(leg.contains("stroke_left_m"));
  }
}

// Case A lands level and symmetric: over every edge the centre of mass lies half the joints' side
// inside and the same height h above the joint centres, so each angle is atan(inside / h), with h
// from the whole lander's centre of mass and the joints at the end.
TEST(LanderSupportEdges, LevelSymmetricStanceTipsAtTheClosedFormOverEveryEdge) {
  const LanderRun run = RunLanderScenario(test::CoarseScenario("lander_case_A"));
  const nlohmann::json edges = LanderSummaryJson(run)["support_edges_at_end"];
  ASSERT_EQ(edges.size(), static_cast<size_t>(lander::kNumLegs));
  const lander::LanderSample& end = run.result.trace.back();
  const lander::LanderModel& m = run.setup.model;
  // The whole lander's centre of mass: body and pads (the legs are massless links).
  double mass = m.body_mass_kg;
  Eigen::Vector3d moment = m.body_mass_kg * end.p_WB;
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const geom::PadBody& pad = *m.legs[i].pad;
    mass += pad.mass_kg;
    moment += pad.mass_kg * (end.p_WJ[i] + Eigen::Quaterniond(end.q_WP[i][0], end.q_WP[i][1], end.q_WP[i][2],
                                                              end.q_WP[i][3]).toRotationMatrix() * pad.com_B);
  }
  const Eigen::Vector3d com = moment / mass;
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const int next = (i + 1) % lander::kNumLegs;
    EXPECT_EQ(edges[i]["pads"][0], i + 1);
    EXPECT_EQ(edges[i]["pads"][1], next + 1);
    const Eigen::Vector3d a = end.p_WJ[i], b = end.p_WJ[next];
    const Eigen::Vector3d mid = 0.5 * (a + b);
    const double inside = std::hypot(mid.x() - com.x(), mid.y() - com.y());
    const double h = com.z() - mid.z();
    EXPECT_NEAR(edges[i]["static_tip_angle_deg"].get<double>(), std::atan2(inside, h) / units::kDeg, 1e-6);
    EXPECT_GT(edges[i]["barrier_J"].get<double>(), 0.0);
  }
}

// A leg's stated load limit: the summary says whether and when its load passed it (case A's rigid
// legs peak at about 101 N each), and a resolved copy of the scenario carries the limit.
TEST(LanderLoadLimit, TheSummarySaysWhetherAndWhenEachLegPassedItsLimit) {
  for (const double limit : {90.0, 120.0}) {
    LanderScenario scenario = test::CoarseScenario("lander_case_A");
    for (LanderLegSpec& leg : scenario.lander.legs) leg.load_limit_N = limit;
    const LanderRun run = RunLanderScenario(scenario);
    const nlohmann::json legs = LanderSummaryJson(run)["legs"];
    for (int i = 0; i < lander::kNumLegs; ++i) {
      double first = NAN;
      for (const lander::LanderSample& s : run.result.trace)
        if (std::isnan(first) && std::abs(LegAxialForce(scenario.lander, s, i)) > limit) first = s.t_s;
      EXPECT_EQ(legs[i]["load_limit_N"].get<double>(), limit);
      EXPECT_EQ(legs[i]["over_limit"].get<bool>(), !std::isnan(first)) << limit;
      EXPECT_EQ(legs[i]["over_limit"].get<bool>(), legs[i]["peak_axial_force_N"].get<double>() > limit);
      if (!std::isnan(first)) EXPECT_EQ(legs[i]["over_limit_time_s"].get<double>(), first);
      else EXPECT_FALSE(legs[i].contains("over_limit_time_s"));
    }
  }
  // Without a limit the summary states none.
  const nlohmann::json legs = LanderSummaryJson(RunLanderScenario(test::CoarseScenario("lander_case_A")))["legs"];
  EXPECT_FALSE(legs[0].contains("load_limit_N"));
  EXPECT_FALSE(legs[0].contains("over_limit"));
}

}  // namespace
}  // namespace touchdown::scenario
