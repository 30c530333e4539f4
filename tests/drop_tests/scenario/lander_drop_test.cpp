// Lander scenarios: the single-pad limit against the rig, slopes and tip-over, placement on the
// surface, input errors and the summary (the lander on its own: tests/lander/multibody/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>

#include "drop_tests/scenario/lander_outputs.h"
#include "lander/pad/rig_drop.h"
#include "rft/contact_wrench.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "rft/units.h"

namespace touchdown::lander {
namespace {

using units::kDeg;

const scenario::LanderRun& CaseRun(const std::string& name) {
  static std::map<std::string, scenario::LanderRun> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, RunLanderScenario(test::CoarseScenario(name))).first;
  return it->second;
}

TEST(LanderDrop, RigidLanderLandingFlatMatchesSinglePadWithAQuarterOfTheMass) {
  const scenario::LanderRun& run = CaseRun("lander_case_A");
  // The same pad, the same 3D contact (the soil's dynamic term included), on the rig's vertical
  // rod with a quarter of the mass.
  const geom::PadBody& pad = run.scenario.lander.pad.body;
  const rft::PlaneGround ground;
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  const rft::SoilContactModel contact = rft::MakeSoilContactModel(
      rft::LawKind::kLi2013, soil, run.scenario.gravity_m_s2, rft::WithSoilDynamicTerm({}, soil));
  const pad::FunctionSoilResponse resistance([&](double depth, double speed_down) {
    rft::PadKinematics k;
    k.p_WB = Eigen::Vector3d(0, 0, -pad.lowest_z_B - depth);
    k.v_WB_W = Eigen::Vector3d(0, 0, -std::max(speed_down, 1e-12));  // at rest: the direction only
    return rft::ComputeContactWrench(pad.surface, k, ground, *contact.law).force_W.z();
  });
  pad::RigDropSetup single_pad;
  single_pad.body.mass_kg = run.scenario.lander.total_mass_kg / 4.0;
  single_pad.terrain = &resistance;
  single_pad.initial.gravity_m_s2 = run.scenario.gravity_m_s2;
  single_pad.initial.impact_speed_m_s = std::sqrt(2.0 * run.scenario.gravity_m_s2 * *run.scenario.initial.drop_height_m);
  single_pad.options.rest_duration_s = 0.0;
  const pad::RigDropResult single = pad::RunRigDrop(single_pad);
  const double lander_depth = run.result.final_penetration_m[0];
  std::printf("[ single pad ] lander %.4f mm, single pad (m/4) %.4f mm\n", lander_depth * 1e3,
              single.final_penetration_m * 1e3);
  EXPECT_NEAR(lander_depth / single.final_penetration_m, 1.0, 0.02);
}

scenario::LanderRun SlopeRun(double slope_deg, double sideways_m_s) {
  scenario::LanderScenario s = test::CoarseScenario("lander_case_A");
  s.ground.slope_rad = slope_deg * kDeg;
  s.ground.downhill_azimuth_rad = -90.0 * kDeg;  // downhill towards -y: the lander's right side
  s.initial.align_to_slope = true;
  s.initial.yaw_relative_to_slope_rad = 90.0 * kDeg;  // body x across the slope
  s.initial.drop_height_m = 0.05;
  s.initial.horizontal_velocity_m_s = Eigen::Vector2d(0.0, -sideways_m_s);  // sliding downhill
  s.options.duration_s = 1.5;
  return RunLanderScenario(s);
}

TEST(LanderDrop, SteepSlopeWithSidewaysSpeedTipsOverAndGentleOneDoesNot) {
  const scenario::LanderRun steep = SlopeRun(30.0, 1.5);
  const scenario::LanderRun gentle = SlopeRun(5.0, 0.2);
  std::printf("[ slope ] steep 30 deg, 1.5 m/s: tipped %d, max tilt %.1f deg; gentle 5 deg, 0.2 m/s: tipped %d, "
              "max tilt %.1f deg\n",
              steep.result.tipped_over, steep.result.max_tilt_rad / kDeg, gentle.result.tipped_over,
              gentle.result.max_tilt_rad / kDeg);
  EXPECT_TRUE(steep.result.tipped_over);
  EXPECT_FALSE(gentle.result.tipped_over);
  EXPECT_TRUE(gentle.result.rest_time_s);
  EXPECT_LT(gentle.result.max_tilt_rad, 15.0 * kDeg);
}

TEST(LanderScenario, BadInputNamesFileFieldAndValue) {
  const std::string dir = ::testing::TempDir();
  auto expect_error = [&](const std::string& text, const std::string& needle) {
    const std::string path = dir + "/lander_bad.yaml";
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    try {
      scenario::LoadLanderScenario(path);
      ADD_FAILURE() << "no error for: " << needle;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;
      EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
  };
  const std::string head = "schema_version: 1\ntype: lander\nlander: sutoh2017_lander\n";
  expect_error(head + "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: -0.1}\n", "initial.drop_height_m");
  expect_error(head + "ground: {soil: mud}\ninitial: {drop_height_m: 0.1}\n", "mud");
  expect_error(head + "ground: {soil: fjs1_lp, slope_degs: 3}\ninitial: {drop_height_m: 0.1}\n", "slope_degs");
  expect_error(head + "ground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1, touchdown_speed_m_s: 1}\n",
               "initial.drop_height_m");
  expect_error(head +
                   "ground: {soil: fjs1_lp, patches: [{soil: fjs1_cp, under_pad: 5, half_width_m: 0.1}]}\n"
                   "initial: {drop_height_m: 0.1}\n",
               "ground.patches[0].under_pad");
  expect_error("schema_version: 1\ntype: lander\nlander: nowhere\nground: {soil: fjs1_lp}\ninitial: {drop_height_m: 0.1}\n",
               "nowhere");
}

}  // namespace
}  // namespace touchdown::lander

// A lander placed on the surface (touchdown_speed_m_s: 0) touches down at t = 0, not never:
// its touchdown times must not be null while the pads sink.
namespace touchdown::lander {
namespace {
TEST(LanderDrop, PlacedOnTheSurfaceTouchesDownAtTimeZero) {
  scenario::LanderScenario s = test::CoarseScenario("lander_case_A");
  s.initial.drop_height_m.reset();
  s.initial.touchdown_speed_m_s = 0.0;
  s.options.duration_s = 0.3;
  const scenario::LanderRun run = RunLanderScenario(s);
  ASSERT_TRUE(run.result.first_touchdown_s.has_value());
  EXPECT_EQ(*run.result.first_touchdown_s, 0.0);
  int touching = 0;
  for (int i = 0; i < lander::kNumLegs; ++i)
    if (run.result.touchdown_time_s[i]) {
      ++touching;
      EXPECT_EQ(*run.result.touchdown_time_s[i], 0.0) << "pad " << i + 1;
    }
  EXPECT_EQ(touching, lander::kNumLegs);  // case A is level: all four pads are placed on the surface
  for (double d : run.result.final_penetration_m) EXPECT_GT(d, 0.0);
  const nlohmann::json j = scenario::LanderSummaryJson(run);
  for (const auto& t : j["touchdown_time_s"]) EXPECT_TRUE(t.is_number()) << j["touchdown_time_s"].dump();
  EXPECT_EQ(j["touchdown_pads"], nlohmann::json({1, 2, 3, 4}));
}

bool HoldsNull(const nlohmann::json& j) {
  if (j.is_null()) return true;
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return true;
  for (const auto& item : j) if ((j.is_object() || j.is_array()) && HoldsNull(item)) return true;
  return false;
}

// A run that ends before any pad touches down and before rest: the summary says so in booleans and
// lists, never with null for a number.
TEST(LanderDrop, SummaryOfARunThatNeverLandsHoldsNoNull) {
  scenario::LanderScenario s = test::CoarseScenario("lander_case_A");
  s.options.duration_s = 0.01;  // released 10 cm up: touchdown comes after about 0.14 s
  const nlohmann::json j = scenario::LanderSummaryJson(RunLanderScenario(s));
  EXPECT_FALSE(HoldsNull(j)) << j.dump();
  EXPECT_EQ(j["came_to_rest"], false);
  EXPECT_TRUE(j["touchdown_pads"].empty());
  EXPECT_TRUE(j["touchdown_time_s"].empty());
  EXPECT_FALSE(j.contains("time_to_rest_s"));
}
}  // namespace
}  // namespace touchdown::lander
