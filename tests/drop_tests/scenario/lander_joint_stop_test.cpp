// A pad hanging against its joint's stop must keep it. On this landing of the lunar study (landing
// d1059 of data/studies/lunar_paper_lander.yaml, rebuilt from its record, on the study's fast model)
// the lander rocks on its held pads 1 and 2 while pads 3 and 4 hang in the air pressed against their
// stops, at the rim to within their attitudes' integration error. With the stop switched off again at the
// rim itself, that error crossed it every few milliseconds, and at one crossing whose root function
// was exactly zero where the integrator restarted CVODE counted the root from the far side: the stop
// was lost and pad 4 swung on to 178 deg, upside down. The stop is off again only 100 rtol inside the
// rim (lander_hybrid.cpp, StopHysteresis).
#include <gtest/gtest.h>

#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "rft/units.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::scenario {
namespace {

struct LanderJointStop : testing_scratch::ScratchDirTest {};

TEST_F(LanderJointStop, APadHangingAgainstItsStopKeepsIt) {
  // CP under pads 1 and 3, LP under pads 2 and 4; 4.7 deg slope; 0.95 m/s at 23 deg from downhill.
  const std::string path = Write(
      "d1059.yaml", test::LunarStudyLandingYaml({.name = "d1059",
                                                 .slope_deg = 4.66822839223839,
                                                 .vx_m_s = 0.8757584566840529,
                                                 .vy_m_s = 0.36701439598657976,
                                                 .roll_deg = -0.0199678280703786,
                                                 .pitch_deg = 1.95383762765602,
                                                 .yaw_relative_to_slope_deg = 14.2883782034583,
                                                 .soils = {"fjs1_cp", "fjs1_lp", "fjs1_cp", "fjs1_lp"}}));
  const LanderRun run = RunLanderScenario(LoadLanderScenario(path));
  const lander::LanderRunResult& r = run.result;
  ASSERT_TRUE(r.rest_time_s.has_value());
  EXPECT_FALSE(r.tipped_over);
  // The stops' 30 deg range and their over-travel: 30.40 deg at most (stop off at the rim: 177.8 deg).
  EXPECT_LT(r.max_joint_swing_rad, 31.0 * units::kDeg);
  int reached = 0, left = 0;
  for (const lander::LanderEvent& e : r.events) {
    reached += e.kind == lander::LanderEventKind::kStopReached;
    left += e.kind == lander::LanderEventKind::kStopLeft;
  }
  // Regression pins: 9 stops reached and 9 left, 720 solver steps, rest at 1.95 s (stop off at the
  // rim: 782 steps, rest at 2.38 s).
  EXPECT_LE(reached - left, 4);
  EXPECT_LT(reached, 15);
  EXPECT_LT(r.solver.steps, 1000);
  EXPECT_NEAR(*r.rest_time_s, 1.95, 0.05);
}

}  // namespace
}  // namespace touchdown::scenario
