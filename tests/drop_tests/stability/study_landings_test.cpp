// Tiny real studies whose answer is known by construction, run by the sweep engine and analysed:
// every landing stays up (level ground, slow, symmetric: probability 0) or every landing tips
// over (a 30 deg slope with 1.5 m/s downhill); the probability and its exact interval follow.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/sweep/sweep.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/drop_tests/stability/study_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {

struct StudyLandings : testing_scratch::ScratchDirTest {
  StudySummary RunStudy(const std::string& body) {
    Study study = LoadStudy(Write("study.yaml", std::string("schema_version: 1\ntype: stability\nname: known\n"
                                                            "lander: {scenario: ") +
                                                    TOUCHDOWN_SOURCE_DIR + "/data/scenarios/lander_case_A.yaml}\n" +
                                                    body));
    test::CoarsenPad(*study.plan.lander);  // a few hundred triangles per pad: milliseconds per landing
    sweep::SweepRunOptions options;
    options.threads = 2;
    options.progress = sweep::ProgressMode::kNone;
    sweep::RunSweep(study.plan, Path("out"), options);
    return test::AnalyseStudy(study, Path("out"));
  }
};

TEST_F(StudyLandings, LevelSlowSymmetricLandingsNeverTipOver) {
  const StudySummary s = RunStudy("grid: {impact_speed_m_s: [0.6, 1.0]}\n");
  EXPECT_EQ(s.landings, 2);
  EXPECT_EQ(s.failed, 0);
  EXPECT_EQ(s.tipped, 0);
  EXPECT_EQ(s.tip_over_probability, 0.0);
  EXPECT_EQ(s.interval.low, 0.0);
  EXPECT_NEAR(s.interval.high, 1.0 - std::sqrt(0.025), 1e-12);  // 0 of 2: 1 - 0.025^(1/2)
  EXPECT_EQ(s.unsettled, 0);
  EXPECT_LT(s.metrics.at(0).max, 0.01);  // symmetric: no tilt
  // The tip-over margin stays well inside the support polygon, as the outcome says.
  EXPECT_EQ(s.margin_checked, 2);
  EXPECT_EQ(s.margin_disagreements, 0);
  for (const sweep::DropRecord& r : s.worst_tilt) EXPECT_GT(r.min_stability_margin_m, 0.05) << r.drop_id;
  // Nothing near the boundary to re-check; the pads never reach their stops.
  ASSERT_TRUE(s.recheck && s.joint_range);
  EXPECT_EQ(s.recheck->rechecked, 0);
  EXPECT_FALSE(std::filesystem::exists(Path("out/recheck")));
  EXPECT_TRUE(s.joint_range->cone_limit);
  EXPECT_EQ(s.joint_range->at_stops, 0);
  EXPECT_FALSE(s.joint_range->ran);
  EXPECT_NE(s.joint_range->reason.find("not more than 5 %"), std::string::npos) << s.joint_range->reason;
  EXPECT_FALSE(std::filesystem::exists(Path("out/joint_range_x0.5")));
}

TEST_F(StudyLandings, SteepSlopeWithFastDownhillSpeedAlwaysTipsOver) {
  const StudySummary s = RunStudy(
      "fixed: {slope_deg: 30, downhill_azimuth_deg: -90, yaw_relative_to_slope_deg: 90, horizontal_speed_m_s: 1.5,\n"
      "        horizontal_azimuth_deg: -90}\n"
      "grid: {impact_speed_m_s: [0.8, 1.0]}\n");
  EXPECT_EQ(s.landings, 2);
  EXPECT_EQ(s.tipped, 2);
  EXPECT_EQ(s.tip_over_probability, 1.0);
  EXPECT_NEAR(s.interval.low, std::sqrt(0.025), 1e-12);  // 2 of 2: 0.025^(1/2)
  EXPECT_EQ(s.interval.high, 1.0);
  EXPECT_EQ(s.tip_overs.size(), 2u);
  // The margin reached zero at the tip-over event: <= 0 on both, as the outcome says.
  EXPECT_EQ(s.margin_checked, 2);
  EXPECT_EQ(s.margin_disagreements, 0);
  for (const sweep::DropRecord& r : s.tip_overs) {
    EXPECT_LE(r.min_stability_margin_m, 0.0) << r.drop_id;
    EXPECT_GT(r.min_stability_margin_m, -0.01) << r.drop_id;  // found at the crossing, not far past it
  }
  EXPECT_EQ(s.metrics.at(0).count, 0);  // no landing stayed up
  // Both tip-overs re-run with the reference model (its records in out/recheck/), and both tip.
  ASSERT_TRUE(s.recheck && s.joint_range);
  EXPECT_EQ(s.recheck->rechecked, 2);
  EXPECT_EQ(s.recheck->outcome_changed, 0);
  EXPECT_EQ(sweep::ResultsDb(sweep::ResultsDbPath(Path("out/recheck"))).Count(), 2);
  // Tipping over swings the pads to their stops: the range's sensitivity on K = 2 landings.
  const JointRangeReport& j = *s.joint_range;
  EXPECT_EQ(j.at_stops, 2);
  ASSERT_TRUE(j.ran) << j.reason;
  EXPECT_EQ(j.samples, 2);
  ASSERT_EQ(j.variants.size(), 3u);
  EXPECT_EQ(j.variants[1].tipped, 2);  // x1: the study's own (reference) records
  EXPECT_NEAR(j.variants[0].half_angle_deg, 15.0, 1e-12);
  EXPECT_NEAR(j.variants[2].half_angle_deg, 45.0, 1e-12);
  for (const JointRangeVariant& v : j.variants) EXPECT_EQ(v.landings, 2);
  EXPECT_EQ(sweep::ResultsDb(sweep::ResultsDbPath(Path("out/joint_range_x1.5"))).Count(), 2);
}

}  // namespace
}  // namespace touchdown::stability
