// A stability study estimated by subset simulation: the method's name checked at load, the
// landing's limit state from its margin and outcome, the study's variables mapped from
// standard-normal space, and a tiny study whose estimate, landings and design points are the same
// on one thread and on two, and after a rerun that finds every landing stored.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_rare_event.h"
#include "drop_tests/stability/study_summary.h"
#include "drop_tests/sweep/sweep.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {

TEST(StudyMethodNames, ParseTheThreeAndRefuseAnythingElseNamingTheOption) {
  EXPECT_EQ(ParseStudyMethod("monte_carlo"), StudyMethod::kMonteCarlo);
  EXPECT_EQ(ParseStudyMethod("subset"), StudyMethod::kSubset);
  EXPECT_EQ(ParseStudyMethod("importance"), StudyMethod::kImportance);
  try {
    ParseStudyMethod("Subset");
    FAIL() << "accepted 'Subset'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--method"), std::string::npos) << what;
    EXPECT_NE(what.find("'Subset'"), std::string::npos) << what;
    EXPECT_NE(what.find("must be monte_carlo, subset or importance"), std::string::npos) << what;
  }
}

TEST(LandingLimitState, IsTheMarginOnTheSideTheOutcomeSays) {
  sweep::DropRecord r;
  r.ok = true;
  r.tipped_over = 0.0;
  r.min_stability_margin_m = 0.12;
  EXPECT_EQ(LimitStateOfLanding(r), 0.12);
  EXPECT_TRUE(MarginAgreesWithOutcome(r));
  r.tipped_over = 1.0;
  r.min_stability_margin_m = -1e-6;
  EXPECT_EQ(LimitStateOfLanding(r), -1e-6);
  EXPECT_TRUE(MarginAgreesWithOutcome(r));
  r.min_stability_margin_m = 0.01;  // disagrees: the outcome decides the side, the check says so
  EXPECT_FALSE(MarginAgreesWithOutcome(r));
  EXPECT_LE(LimitStateOfLanding(r), 0.0);
  r.tipped_over = 0.0;
  r.min_stability_margin_m = -0.01;
  EXPECT_FALSE(MarginAgreesWithOutcome(r));
  EXPECT_GT(LimitStateOfLanding(r), 0.0);
  r.ok = false;  // a failed landing counts as not tipped over
  EXPECT_EQ(LimitStateOfLanding(r), INFINITY);
  EXPECT_TRUE(MarginAgreesWithOutcome(r));
}

// The paper's lander with 16-segment pads for 1 s (data/studies/lab_coarse_lander_scenario.yaml),
// landing on a slope with its horizontal velocity downhill.
const std::string kCoarseScenario = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/studies/lab_coarse_lander_scenario.yaml";

struct RareEventStudy : testing_scratch::ScratchDirTest {
  Study Load(const std::string& random) {
    return LoadStudy(Write("study.yaml", "schema_version: 1\ntype: stability\nname: rare\nlander: {scenario: " +
                                             kCoarseScenario +
                                             "}\nfixed: {downhill_azimuth_deg: -90, yaw_relative_to_slope_deg: 90,"
                                             " horizontal_azimuth_deg: -90}\n" + random));
  }
};

TEST_F(RareEventStudy, TheOriginOfStandardNormalSpaceIsEachUniformsMidpoint) {
  const Study study = Load("random: {samples: 10, seed: 5, slope_deg: {uniform: [0, 30]},\n"
                           "         horizontal_speed_m_s: {uniform: [0, 1.5]}}\n");
  const nlohmann::json v = StudyVariablesJson(study, Eigen::Vector2d(0.0, 1.959963984540054));
  EXPECT_NEAR(v["slope_deg"].get<double>(), 15.0, 1e-9);
  EXPECT_NEAR(v["horizontal_speed_m_s"].get<double>(), 1.5 * 0.975, 1e-9);
}

TEST_F(RareEventStudy, GridsAndChainsThatDoNotDivideAreRefusedAtLoad) {
  const Study grid = Load("grid: {slope_deg: [0, 30]}\n");
  EXPECT_THROW(RequireRareEventStudy(grid, StudyMethod::kSubset, 10), InputError);
  EXPECT_NO_THROW(RequireRareEventStudy(grid, StudyMethod::kMonteCarlo, 10));
  const Study random = Load("random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 30]}}\n");
  EXPECT_THROW(RequireRareEventStudy(random, StudyMethod::kSubset, 15), InputError);
  EXPECT_NO_THROW(RequireRareEventStudy(random, StudyMethod::kSubset, 20));
}

// Slopes up to 20 deg with up to 1.5 m/s downhill tip rarely enough (measured: P about 0.08 in
// 18 landings, two levels) that subset simulation runs its chains.
constexpr const char* kSteepAndFast = "random: {samples: 10, seed: 5, slope_deg: {uniform: [0, 20]},\n"
                                      "         horizontal_speed_m_s: {uniform: [0, 1.5]}}\n";

sweep::SweepRunOptions Quiet(int threads) {
  sweep::SweepRunOptions options;
  options.progress = sweep::ProgressMode::kNone;
  options.threads = threads;
  return options;
}

TEST_F(RareEventStudy, SubsetIsBitIdenticalOnOneThreadAndTwoAndResumes) {
  const Study study = Load(kSteepAndFast);
  sweep::SweepRunOptions options = Quiet(1);
  const RareEventStudyResult one = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("one"), options);
  options.threads = 2;
  const RareEventStudyResult two = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("two"), options);
  const RareEventStudyResult again = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("one"), options);
  ASSERT_GT(one.landings, 10);  // more than the first level: the chains ran
  EXPECT_EQ(one.computed, one.landings);
  EXPECT_EQ(again.computed, 0);
  EXPECT_EQ(again.already_done, one.landings);
  EXPECT_EQ(one.margin_disagreements, 0);
  ASSERT_FALSE(one.design_points.empty());
  for (const RareEventStudyResult* r : {&two, &again}) {
    EXPECT_EQ(r->landings, one.landings);
    EXPECT_EQ(r->failed, one.failed);
    EXPECT_EQ(std::memcmp(&r->estimate.probability, &one.estimate.probability, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&r->estimate.cov, &one.estimate.cov, sizeof(double)), 0);
    EXPECT_EQ(RareEventJson(study, *r).dump(), RareEventJson(study, one).dump());
    ASSERT_EQ(r->first_level.size(), one.first_level.size());
    for (size_t k = 0; k < one.first_level.size(); ++k)
      EXPECT_TRUE(sweep::SameRecord(r->first_level[k], one.first_level[k], false)) << k;
  }
  EXPECT_GT(one.estimate.probability, 0.0);
  EXPECT_LT(one.estimate.probability, 0.1);  // more than one level: below p0
  EXPECT_LE(one.estimate.interval.low, one.estimate.probability);
  EXPECT_GE(one.estimate.interval.high, one.estimate.probability);
}

// Importance sampling's first pass is the subset run: in a folder the subset method filled it runs
// only its own landings (the design point's refinement, 1 + 7 x 4, and its sample, 10) into
// DIR/importance/.
TEST_F(RareEventStudy, ImportanceReusesTheSubsetRunsLandings) {
  const Study study = Load(kSteepAndFast);
  const sweep::SweepRunOptions options = Quiet(2);
  const RareEventStudyResult one = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("one"), options);
  const RareEventStudyResult importance = RunRareEventStudy(study, StudyMethod::kImportance, 10, Path("one"), options);
  ASSERT_EQ(importance.stop_signal, 0);
  EXPECT_EQ(importance.already_done, one.landings);
  EXPECT_EQ(importance.computed, 1 + 7 * kDesignPointRounds + 10);
  EXPECT_EQ(importance.landings, one.landings + importance.computed);
  ASSERT_TRUE(importance.subset.has_value());
  EXPECT_EQ(std::memcmp(&importance.subset->probability, &one.estimate.probability, sizeof(double)), 0);
  ASSERT_TRUE(importance.importance_centre.has_value());
  ASSERT_FALSE(importance.design_points.empty());
  for (size_t k = 0; k < importance.design_points.size(); ++k) {
    const RareEventDesignPoint& d = importance.design_points[k];
    EXPECT_TRUE(d.run == "subset" || d.run == "importance") << d.run;
    if (k > 0) {
      EXPECT_LE(importance.design_points[k - 1].beta, d.beta);
    }
  }
  EXPECT_TRUE(std::filesystem::exists(sweep::ResultsDbPath(Path("one") + "/importance")));
}

}  // namespace
}  // namespace touchdown::stability
