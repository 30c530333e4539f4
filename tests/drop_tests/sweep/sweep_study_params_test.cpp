// The lander-sweep parameters a stability study varies (slope and its azimuth, yaw to the slope,
// the horizontal velocity's azimuth, angular rates, a random soil under each pad): accepted in
// every block, validated at load naming file and field, in the digest and the round trip, drawn
// from the drop index alone, and reaching the lander as the scenario's own fields would.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/round_trip.h"
#include "rft/units.h"

namespace touchdown::sweep {
namespace {

namespace fs = std::filesystem;
using units::kDeg;

std::string StudyLanderHead() {
  return std::string("schema_version: 1\ntype: sweep\nname: study_params\nlander: {scenario: ") + TOUCHDOWN_SOURCE_DIR +
         "/data/scenarios/lander_case_A.yaml}\n";
}

struct SweepStudyParams : testing_scratch::ScratchDirTest {
  std::string WriteText(const std::string& name, const std::string& text) {
    std::ofstream(Path(name)) << text;
    return Path(name);
  }
};

TEST_F(SweepStudyParams, EveryNewParameterLoadsInEveryBlockWithItsUnits) {
  const SweepPlan plan = LoadSweepPlan(WriteText(
      "all.yaml", StudyLanderHead() +
                      "fixed: {downhill_azimuth_deg: 30, angular_rate_x_deg_s: 2, angular_rate_y_deg_s: -3}\n"
                      "grid: {slope_deg: [0, 12.5], yaw_relative_to_slope_deg: {from: 0, to: 90, count: 3}}\n"
                      "random: {samples: 3, seed: 5, horizontal_azimuth_deg: {uniform: [-180, 180]},\n"
                      "         angular_rate_z_deg_s: {choice: [0, 10]}, horizontal_speed_m_s: {uniform: [0, 1]}}\n"));
  ASSERT_EQ(plan.size(), 2 * 3 * 3);
  const SweepDropParams last = plan.DropAt(plan.size() - 1);
  EXPECT_NEAR(last.slope_rad, 12.5 * kDeg, 1e-15);
  EXPECT_NEAR(last.yaw_to_slope_rad, 90.0 * kDeg, 1e-15);
  EXPECT_NEAR(last.downhill_azimuth_rad, 30.0 * kDeg, 1e-15);
  EXPECT_NEAR(last.angular_rate_rad_s[0], 2.0 * kDeg, 1e-15);
  EXPECT_NEAR(last.angular_rate_rad_s[1], -3.0 * kDeg, 1e-15);
  EXPECT_TRUE(last.angular_rate_rad_s[2] == 0.0 || std::abs(last.angular_rate_rad_s[2] - 10.0 * kDeg) < 1e-15);
  EXPECT_LE(std::abs(last.horizontal_azimuth_rad), M_PI);
  for (SweepParam p : {SweepParam::kSlope, SweepParam::kDownhillAzimuth, SweepParam::kYawToSlope,
                       SweepParam::kHorizontalAzimuth, SweepParam::kRateX, SweepParam::kRateY, SweepParam::kRateZ})
    EXPECT_TRUE(last.Given(p)) << SweepParamKey(p);
  EXPECT_FALSE(last.Given(SweepParam::kRoll));
}

// Every lander parameter a study varies is a sweep parameter: `grid.slope_deg: unknown parameter`
// must never come back, nor any of its siblings.
TEST_F(SweepStudyParams, SlopeInTheGridIsNeverAnUnknownParameter) {
  for (const char* key : {"slope_deg", "downhill_azimuth_deg", "yaw_relative_to_slope_deg", "horizontal_azimuth_deg",
                          "angular_rate_x_deg_s", "angular_rate_y_deg_s", "angular_rate_z_deg_s"}) {
    SCOPED_TRACE(key);
    const std::string file = WriteText("grid.yaml", StudyLanderHead() + "grid: {" + key + ": [0, 5]}\n");
    EXPECT_NO_THROW(LoadSweepPlan(file));
  }
}

TEST_F(SweepStudyParams, BadValuesAndMisplacedParametersNameFileAndField) {
  auto expect_error = [&](const std::string& body, const std::string& field, const std::string& reason) {
    const std::string file = WriteText("bad.yaml", body);
    try {
      LoadSweepPlan(file);
      ADD_FAILURE() << "accepted: " << body;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(file), std::string::npos) << what;
      EXPECT_NE(what.find(field), std::string::npos) << what;
      EXPECT_NE(what.find(reason), std::string::npos) << what;
    }
  };
  expect_error(StudyLanderHead() + "grid: {slope_deg: [0, 85]}\n", "grid.slope_deg[1]", "below 80");
  expect_error(StudyLanderHead() + "grid: {slope_deg: [-1]}\n", "grid.slope_deg[0]", "at least 0");
  expect_error(StudyLanderHead() + "fixed: {horizontal_azimuth_deg: 400}\n", "fixed.horizontal_azimuth_deg", "360");
  expect_error(StudyLanderHead() + "grid: {slope_degs: [1]}\n", "grid.slope_degs", "unknown parameter");
  expect_error(
      "schema_version: 1\ntype: sweep\nfixed: {pad: flat, soil: fjs1_lp, impact_speed_m_s: 1, slope_deg: 5}\n",
      "fixed.slope_deg", "lander parameter");
  expect_error(StudyLanderHead() +
                   "random: {samples: 2, seed: 1, pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp], "
                   "probabilities: [0.5, 0.6]}}\n",
               "random.pad_soils.probabilities", "sum to 1");
  expect_error(StudyLanderHead() +
                   "random: {samples: 2, seed: 1, pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp], "
                   "probabilities: [0.5]}}\n",
               "random.pad_soils.probabilities", "2 numbers");
  expect_error(StudyLanderHead() + "random: {samples: 2, seed: 1, roll_deg: {per_pad_choice: [1, 2]}}\n",
               "random.roll_deg.per_pad_choice", "only pad_soils");
  expect_error(StudyLanderHead() + "random: {samples: 2, seed: 1, roll_deg: {uniform: [0, 1], probabilities: [1]}}\n",
               "random.roll_deg.probabilities", "only a choice");
  expect_error(StudyLanderHead() + "study: {}\n", "study", "type: stability");
}

TEST_F(SweepStudyParams, PerPadSoilsAreDrawnPerPadFromTheIndexWithTheirProbabilities) {
  const std::string body = "random: {samples: 4000, seed: 3, pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp], "
                           "probabilities: [0.25, 0.75]}}\n";
  const SweepPlan plan = LoadSweepPlan(WriteText("per_pad.yaml", StudyLanderHead() + body));
  const SweepPlan again = LoadSweepPlan(WriteText("per_pad_again.yaml", StudyLanderHead() + body));
  ASSERT_EQ(plan.pad_soil_sets.size(), 16u);  // 2^4 combinations
  std::array<int, 4> cp{};
  int all_lp = 0;
  for (int64_t i = plan.size(); i-- > 0;) {  // any order: a drop's draw depends on its index only
    const SweepDropParams p = plan.DropAt(i);
    ASSERT_EQ(p.pad_soils, again.DropAt(i).pad_soils);
    const PadSoilSet& set = plan.pad_soil_sets.at(p.pad_soils);
    bool lp = true;
    for (int pad = 0; pad < 4; ++pad) {
      const bool is_cp = plan.soils.at(set.soil[pad]).name == "fjs1_cp";
      cp[pad] += is_cp;
      lp = lp && !is_cp;
    }
    all_lp += lp;
  }
  // Binomial(4000, 0.75): standard deviation 27; 4.5 sigma bounds. All four LP: 0.25^4 = 1/256.
  for (int pad = 0; pad < 4; ++pad) EXPECT_NEAR(cp[pad], 3000, 125) << "pad " << pad + 1;
  EXPECT_NEAR(all_lp, 4000.0 / 256.0, 17.0);
  // Probability 0 is never drawn.
  const SweepPlan only_lp = LoadSweepPlan(WriteText(
      "only_lp.yaml", StudyLanderHead() + "random: {samples: 200, seed: 3, pad_soils: {per_pad_choice: "
                                          "[fjs1_lp, fjs1_cp], probabilities: [1, 0]}}\n"));
  for (int64_t i = 0; i < only_lp.size(); ++i)
    for (int soil : only_lp.pad_soil_sets.at(only_lp.DropAt(i).pad_soils).soil)
      ASSERT_EQ(only_lp.soils.at(soil).name, "fjs1_lp");
}

TEST_F(SweepStudyParams, NewParametersRoundTripAndChangeTheDigest) {
  const std::string file = WriteText(
      "round.yaml", StudyLanderHead() +
                        "fixed: {downhill_azimuth_deg: -90, angular_rate_z_deg_s: 4}\n"
                        "grid: {slope_deg: [0, 7.5]}\n"
                        "random: {samples: 5, seed: 9, yaw_relative_to_slope_deg: {uniform: [-180, 180]},\n"
                        "  horizontal_azimuth_deg: {choice: [0, 90, 180], probabilities: [0.2, 0.3, 0.5]},\n"
                        "  pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp], probabilities: [0.5, 0.5]}}\n");
  const SweepPlan plan = LoadSweepPlan(file);
  testing_scratch::ExpectRoundTrip(
      plan, Path("round_1.yaml"), Path("round_2.yaml"), WriteSweepPlan,
      [](const std::string& path) { return LoadSweepPlan(path); },
      [](const SweepPlan& a, const SweepPlan& b) {
        EXPECT_EQ(a.DigestText(), b.DigestText());
        ASSERT_EQ(a.size(), b.size());
        for (int64_t i = 0; i < a.size(); ++i) {
          const SweepDropParams p = a.DropAt(i), q = b.DropAt(i);
          EXPECT_EQ(p.slope_rad, q.slope_rad);
          EXPECT_EQ(p.downhill_azimuth_rad, q.downhill_azimuth_rad);
          EXPECT_EQ(p.yaw_to_slope_rad, q.yaw_to_slope_rad);
          EXPECT_EQ(p.horizontal_azimuth_rad, q.horizontal_azimuth_rad);
          EXPECT_EQ(p.angular_rate_rad_s, q.angular_rate_rad_s);
          EXPECT_EQ(p.pad_soils, q.pad_soils);
          EXPECT_EQ(p.given, q.given);
        }
      });
  // Every new parameter is in the digest: another probability or slope is another sweep.
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  auto digest_with = [&](const std::string& from, const std::string& to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    return PlanDigest(LoadSweepPlan(WriteText("changed.yaml", changed)));
  };
  const std::string digest = PlanDigest(plan);
  EXPECT_NE(digest_with("[0, 7.5]", "[0, 7.6]"), digest);
  EXPECT_NE(digest_with("[0.2, 0.3, 0.5]", "[0.3, 0.2, 0.5]"), digest);
  EXPECT_NE(digest_with("angular_rate_z_deg_s: 4", "angular_rate_z_deg_s: 5"), digest);
}

// A slope (and the motion relative to it) set by the sweep lands exactly as the scenario with the
// same fields set in it: bit for bit, and recorded in the format-5 columns.
TEST_F(SweepStudyParams, SlopeAndMotionReachTheLanderAsTheScenarioFieldsWould) {
  SweepPlan plan = LoadSweepPlan(WriteText(
      "slope.yaml", StudyLanderHead() + "fixed: {slope_deg: 8, downhill_azimuth_deg: 90, yaw_relative_to_slope_deg: 30,\n"
                                        "  horizontal_speed_m_s: 0.2, horizontal_azimuth_deg: 90, angular_rate_x_deg_s: 3,\n"
                                        "  impact_speed_m_s: 1.0}\n"));
  test::CoarsenPad(*plan.lander);
  const SweepModels models(plan);
  const DropRecord r = SimulateSweepDrop(models, 0);
  ASSERT_TRUE(r.ok) << r.failure;

  scenario::LanderScenario sc = *plan.lander;
  sc.ground.slope_rad = 8.0 * kDeg;
  sc.ground.downhill_azimuth_rad = 90.0 * kDeg;
  sc.initial.yaw_relative_to_slope_rad = 30.0 * kDeg;
  sc.initial.horizontal_velocity_m_s = 0.2 * Eigen::Vector2d(std::cos(90.0 * kDeg), std::sin(90.0 * kDeg));
  sc.initial.angular_rate_B.x() = 3.0 * kDeg;
  sc.initial.drop_height_m.reset();
  sc.initial.touchdown_speed_m_s = 1.0;
  sc.options.integrator.max_rhs_evaluations = plan.rig.integrator.max_rhs_evaluations;
  const scenario::LanderRun direct = scenario::RunLanderScenario(sc);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(r.pad_final_penetration_m[i], direct.result.final_penetration_m[i]) << i;
    EXPECT_EQ(r.pad_peak_force_N[i], direct.result.peak_pad_force_N[i]) << i;
  }
  EXPECT_EQ(r.max_tilt_deg, direct.result.max_tilt_rad / kDeg);
  EXPECT_EQ(r.final_tilt_deg, direct.result.final_attitude.tilt_rad / kDeg);
  EXPECT_NEAR(r.slope_deg, 8.0, 1e-12);
  EXPECT_NEAR(r.downhill_azimuth_deg, 90.0, 1e-12);
  EXPECT_NEAR(r.yaw_relative_to_slope_deg, 30.0, 1e-12);
  EXPECT_NEAR(r.horizontal_azimuth_deg, 90.0, 1e-12);
  EXPECT_NEAR(r.angular_rate_deg_s[0], 3.0, 1e-12);
  EXPECT_EQ(r.angular_rate_deg_s[2], 0.0);
  // On an 8 deg slope the body tilts by about the slope at rest; the rigid legs carry the load
  // (no absorbers: no stroke), at least the lander's weight shared over four legs.
  EXPECT_GT(r.max_tilt_deg, 4.0);
  EXPECT_TRUE(std::isnan(r.max_stroke_m));
  EXPECT_GT(r.peak_leg_force_N, 4.3 * 9.81 / 4.0);
  // Stored and sent between ranks bit for bit, format-5 columns included.
  {
    ResultsDb db(Path("results.sqlite"));
    db.Insert({r});
    ASSERT_TRUE(SameRecord(db.ReadAll(false).at(0), r, false));
  }
  EXPECT_TRUE(SameRecord(DeserializeRecords(SerializeRecords({r})).at(0), r));
}

// The pad design on all four legs: the lander's own pad gives back its legs exactly; a wider pad
// (same mass and joint height) sinks less; a pad heavier than the lander can carry is refused at load.
TEST_F(SweepStudyParams, PadDesignPlacesTheLegsAndSinksByItsSize) {
  const std::string pad_text = std::string("schema_version: 1\nkind: axisymmetric\nmass_kg: 0.08\nangular_segments: 16\n") +
                               "reference_point_mm: [0, 0, 20]\nprofile: {shape: flat, thickness_mm: 10, radius_mm: ";
  const std::string own = WriteText("own_pad.yaml", "name: own\n" + pad_text + "27.5}\n");
  const std::string wide = WriteText("wide_pad.yaml", "name: wide\n" + pad_text + "40}\n");
  const SweepPlan plan =
      LoadSweepPlan(WriteText("pads.yaml", StudyLanderHead() + "grid: {pad: [" + own + ", " + wide + "]}\n"));
  ASSERT_EQ(plan.pads.size(), 2u);
  const scenario::LanderSpec& spec = plan.lander->lander;
  const scenario::LanderSpec again = scenario::LanderSpecWithPad(spec, spec.pad);
  EXPECT_EQ(again.body_mass_kg, spec.body_mass_kg);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(again.legs[i].joint_B, spec.legs[i].joint_B) << i;
    EXPECT_EQ(again.legs[i].hip_B, spec.legs[i].hip_B) << i;
  }
  const SweepModels models(plan);
  const DropRecord narrow_drop = SimulateSweepDrop(models, 0), wide_drop = SimulateSweepDrop(models, 1);
  ASSERT_TRUE(narrow_drop.ok && wide_drop.ok) << narrow_drop.failure << wide_drop.failure;
  EXPECT_EQ(narrow_drop.pad, "own");
  EXPECT_EQ(wide_drop.pad, "wide");
  // RFT: the force grows with the footprint, so the 2.1x larger pad stops in a shallower stroke.
  EXPECT_LT(wide_drop.final_penetration_m, 0.8 * narrow_drop.final_penetration_m);

  const std::string heavy =
      WriteText("heavy_pad.yaml", "name: heavy\n" + std::string(pad_text).replace(pad_text.find("0.08"), 4, "1.2") + "27.5}\n");
  const std::string file = WriteText("heavy.yaml", StudyLanderHead() + "fixed: {pad: " + heavy + "}\n");
  try {
    LoadSweepPlan(file);
    ADD_FAILURE() << "a 1.2 kg pad on each leg of a 4.3 kg lander was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_NE(what.find("pad"), std::string::npos) << what;
    EXPECT_NE(what.find("does not fit"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace touchdown::sweep
