// A study's follow-ups on hand-made records and plans: which landings the re-check criterion
// takes, how the reference records replace the fast ones and what the report counts, the
// standing lander's tip-over angle, the K landings of the joint-range sensitivity, and the derived
// plans (their model changes and their own digests).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/sweep/sweep.h"
#include "rft/units.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {
using sweep::DropRecord;

DropRecord Landing(int64_t index, bool tipped, double max_tilt_deg, bool at_rest = true) {
  DropRecord r;
  r.index = index;
  r.drop_id = sweep::SweepPlan{}.DropId(index);
  r.kind = sweep::DropKind::kLander;
  r.ok = true;
  r.tipped_over = tipped ? 1.0 : 0.0;
  r.max_tilt_deg = max_tilt_deg;
  r.time_to_rest_s = at_rest || tipped ? 0.5 : std::nan("");
  return r;
}

struct StudyFollowUpsTest : testing_scratch::ScratchDirTest {
  Study LoadCaseA(const std::string& body) {
    return LoadStudy(Write("study.yaml", std::string("schema_version: 1\ntype: stability\nname: followups\n"
                                                     "lander: {scenario: ") +
                                             TOUCHDOWN_SOURCE_DIR + "/data/scenarios/lander_case_A.yaml}\n" + body));
  }
};

TEST(RecheckCriterion, TippedOrWithinTheMarginOfTheTipAngleAndUnsettledOnlyWhenAsked) {
  const double tip = 40.0;
  RecheckSettings s;
  s.tilt_margin_deg = 3.0;
  EXPECT_TRUE(NeedsRecheck(Landing(0, true, 90.0), tip, s));          // tipped over
  EXPECT_FALSE(NeedsRecheck(Landing(1, false, 5.0, false), tip, s));  // unsettled, clear of the boundary
  EXPECT_TRUE(NeedsRecheck(Landing(1, false, 37.0, false), tip, s));  // unsettled, at tip - margin
  EXPECT_TRUE(NeedsRecheck(Landing(2, false, 37.0), tip, s));         // at tip - margin
  EXPECT_TRUE(NeedsRecheck(Landing(3, false, 41.0), tip, s));         // past the static angle, stood
  EXPECT_FALSE(NeedsRecheck(Landing(4, false, 36.99), tip, s));       // settled, clear of the boundary
  DropRecord failed = Landing(5, true, 90.0);
  failed.ok = false;
  EXPECT_FALSE(NeedsRecheck(failed, tip, s));  // no outcome to check
  s.unsettled = true;                          // every unsettled landing, as the studies did before
  EXPECT_TRUE(NeedsRecheck(Landing(1, false, 5.0, false), tip, s));
  EXPECT_FALSE(NeedsRecheck(Landing(4, false, 36.99), tip, s));  // settled: the margin alone decides
  EXPECT_FALSE(NeedsRecheck(failed, tip, s));
  s.tilt_margin_deg = 90.0;  // a 90 deg margin takes every landing
  s.unsettled = false;
  EXPECT_TRUE(NeedsRecheck(Landing(4, false, 36.99), tip, s));
  EXPECT_TRUE(NeedsRecheck(Landing(1, false, 5.0, false), tip, s));
}

TEST_F(StudyFollowUpsTest, ReferenceRecordsReplaceTheFastOnesAndTheReportCountsTheChanges) {
  const Study study = LoadCaseA("random: {samples: 4, seed: 1, slope_deg: {uniform: [0, 20]}}\n");
  std::vector<DropRecord> records = {Landing(0, false, 2.0), Landing(1, true, 80.0), Landing(2, false, 38.0),
                                     Landing(3, false, 39.0)};
  DropRecord failed_reference = Landing(3, true, 90.0);
  failed_reference.ok = false;
  const std::vector<DropRecord> reference = {Landing(1, true, 81.5), Landing(2, true, 85.0), failed_reference};
  std::vector<DropRecord> fast;
  const RecheckReport r = ApplyRechecks(study, 40.0, records, reference, &fast);
  EXPECT_EQ(r.rechecked, 3);
  EXPECT_EQ(r.outcome_changed, 1);  // drop 2 tips over with the reference model
  EXPECT_EQ(r.changed_landings, (std::vector<std::string>{records[2].drop_id}));
  EXPECT_EQ(r.reference_failed, 1);  // drop 3: the fast record stays
  EXPECT_DOUBLE_EQ(r.largest_max_tilt_change_deg, 47.0);
  EXPECT_EQ(records[1].max_tilt_deg, 81.5);
  EXPECT_EQ(records[2].tipped_over, 1.0);
  EXPECT_EQ(records[3].max_tilt_deg, 39.0);
  EXPECT_EQ(records[0].max_tilt_deg, 2.0);
  ASSERT_EQ(fast.size(), 2u);
  EXPECT_EQ(fast[1].max_tilt_deg, 38.0);
}

TEST_F(StudyFollowUpsTest, DerivedPlansChangeTheirModelAndTheirDigest) {
  const Study study = LoadCaseA("random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 20]}}\n");
  EXPECT_EQ(study.recheck.rtol, 1e-8);  // the default reference, below the scenario's 1e-7
  EXPECT_EQ(study.recheck.tilt_margin_deg, kDefaultRecheckMarginDeg);
  EXPECT_FALSE(study.recheck.unsettled);  // unsettled landings clear of the margin are not re-run
  EXPECT_EQ(study.joint_range.samples, 1000);
  const sweep::SweepPlan recheck = RecheckPlan(study);
  EXPECT_EQ(recheck.lander->options.integrator.rtol, 1e-8);
  EXPECT_NEAR(ConeHalfAngleDeg(study.plan), 30.0, 1e-12);
  const sweep::SweepPlan narrow = JointRangePlan(study, 0.5), wide = JointRangePlan(study, 1.5);
  for (const scenario::LanderLegSpec& leg : narrow.lander->lander.legs) {
    EXPECT_NEAR(leg.cone->half_angle_rad, 15.0 * units::kDeg, 1e-15);
    EXPECT_EQ(leg.cone->stiffness_N_m_rad, study.plan.lander->lander.legs[0].cone->stiffness_N_m_rad);
  }
  EXPECT_NEAR(wide.lander->lander.layout.cone->half_angle_rad, 45.0 * units::kDeg, 1e-15);
  const std::set<std::string> digests = {sweep::PlanDigest(study.plan), sweep::PlanDigest(recheck),
                                         sweep::PlanDigest(narrow), sweep::PlanDigest(wide)};
  EXPECT_EQ(digests.size(), 4u);
  EXPECT_EQ(recheck.size(), study.plan.size());  // the same landings, by index
  EXPECT_EQ(recheck.DropAt(7).slope_rad, study.plan.DropAt(7).slope_rad);
}

// The shipped lunar study lands coarser pads than their file's, with looser spins (its fast model);
// the reference model of its re-checks meshes them as the file says and resolves the spins as every
// other state, and the report names both meshes.
TEST_F(StudyFollowUpsTest, TheReferenceModelMeshesThePadsAsTheirFileSays) {
  const Study study = LoadStudy(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/studies/lunar_paper_lander.yaml");
  ASSERT_GT(study.plan.lander->pad_angular_segments, 0);
  const sweep::SweepPlan recheck = RecheckPlan(study);
  EXPECT_EQ(recheck.lander->pad_angular_segments, 0);
  EXPECT_EQ(io::PadRimSegments(recheck.lander->lander.pad), study.plan.lander->pad_file_angular_segments);
  EXPECT_EQ(recheck.lander->lander.pad.body.surface.size(),
            io::LoadPad(study.plan.lander->lander.pad.source).body.surface.size());
  EXPECT_GT(recheck.lander->lander.pad.body.surface.size(), study.plan.lander->lander.pad.body.surface.size());
  EXPECT_EQ(recheck.lander->lander.body_mass_kg, study.plan.lander->lander.body_mass_kg);
  // ... and resolves the pads' spins as every other state (the fast model loosens them).
  EXPECT_EQ(study.plan.lander->options.pad_spin_tolerance_factor, 10.0);
  EXPECT_EQ(recheck.lander->options.pad_spin_tolerance_factor, 1.0);
  std::vector<DropRecord> records = {Landing(0, false, 2.0)};
  const RecheckReport r = ApplyRechecks(study, 40.0, records, {}, nullptr);
  EXPECT_EQ(r.fast_pad_angular_segments, study.plan.lander->pad_angular_segments);
  EXPECT_EQ(r.reference_pad_angular_segments, study.plan.lander->pad_file_angular_segments);
  const nlohmann::json j = RecheckJson(r);
  EXPECT_EQ(j["pad_angular_segments"]["fast"], r.fast_pad_angular_segments);
  EXPECT_EQ(j["pad_angular_segments"]["reference"], r.reference_pad_angular_segments);
}

TEST_F(StudyFollowUpsTest, StandingTipAngleIsTheSmallestEdgesAndKSpreadsOverTheStudy) {
  Study study = LoadCaseA("random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 20]}}\n"
                          "study: {joint_range_sensitivity: {samples: 4},\n"
                          "        recheck: {rtol: 1e-9, tilt_margin_deg: 5, unsettled: true}}\n");
  EXPECT_EQ(study.recheck.rtol, 1e-9);
  EXPECT_EQ(study.recheck.tilt_margin_deg, 5.0);
  EXPECT_TRUE(study.recheck.unsettled);
  // The paper's lander standing level: its four edges alike, the CoM as far inside each edge as
  // it is high above it, near enough (45.29 deg, as summary.json reports it for its studies).
  EXPECT_NEAR(StandingTipAngleDeg(study.plan), 45.29, 0.01);
  EXPECT_EQ(JointRangeIndices(study), (std::vector<int64_t>{0, 2, 5, 7}));
  study.joint_range.samples = 1000;  // more than the study has: all of them
  EXPECT_EQ(JointRangeIndices(study).size(), 10u);
}

// The joint-range screen: a landing runs again at the other ranges when it tipped, ended unsettled,
// failed, or its max tilt came within the margin of the tip-over angle; without a screen, always.
TEST_F(StudyFollowUpsTest, TheJointRangeScreenRunsWhatCouldTipAtAnotherRange) {
  const Study study = LoadCaseA("random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 20]}}\n");
  const JointRangeSettings& s = study.joint_range;
  ASSERT_TRUE(s.screen_margin_deg.has_value());
  EXPECT_EQ(*s.screen_margin_deg, kDefaultJointRangeScreenDeg);
  const double tip = 45.0, edge = tip - kDefaultJointRangeScreenDeg;  // 25 deg
  EXPECT_FALSE(MayTipAtAnotherRange(Landing(0, false, 10.0), tip, s));
  EXPECT_FALSE(MayTipAtAnotherRange(Landing(0, false, std::nextafter(edge, 0.0)), tip, s));
  EXPECT_TRUE(MayTipAtAnotherRange(Landing(0, false, edge), tip, s));
  EXPECT_TRUE(MayTipAtAnotherRange(Landing(0, true, 44.0), tip, s));
  EXPECT_TRUE(MayTipAtAnotherRange(Landing(0, false, 10.0, /*at_rest=*/false), tip, s));
  DropRecord failed = Landing(0, false, 10.0);
  failed.ok = false;
  EXPECT_TRUE(MayTipAtAnotherRange(failed, tip, s));
  JointRangeSettings none = s;
  none.screen_margin_deg.reset();
  EXPECT_TRUE(MayTipAtAnotherRange(Landing(0, false, 0.0), tip, none));

  const Study off = LoadCaseA("random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 20]}}\n"
                              "study: {joint_range_sensitivity: {samples: 4, screen_margin_deg: none}}\n");
  EXPECT_FALSE(off.joint_range.screen_margin_deg.has_value());
  EXPECT_EQ(off.joint_range.samples, 4);
  const Study wide = LoadCaseA("random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 20]}}\n"
                               "study: {joint_range_sensitivity: {screen_margin_deg: 35}}\n");
  EXPECT_EQ(wide.joint_range.screen_margin_deg.value_or(0.0), 35.0);
  EXPECT_EQ(wide.joint_range.samples, 1000);
}

}  // namespace
}  // namespace touchdown::stability
