// A pad whose capture the soil refuses and that slides on with its vertical speed at zero (riding in
// the soil's trailing band) would cross the sink-rate root again within a step of each restart. On
// this landing of the lunar study (landing d570 of data/studies/lunar_paper_lander.yaml, rebuilt from
// its record, on the study's fast model) a capture offered at every such crossing costs tens of
// thousands of solver steps in 50 ms of refused captures, and other landings of the study fail on
// 20,000 events. So a refused pad is offered a capture again only when it slows to the soil's ramp
// speed, or after it has been faster than the capture speed (lander_hybrid.cpp, capture_refused_).
#include <gtest/gtest.h>

#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::scenario {
namespace {

struct LanderRefusedCapture : testing_scratch::ScratchDirTest {};

TEST_F(LanderRefusedCapture, ASlidingPadRefusedByTheSoilDoesNotChatter) {
  // CP under pads 1-3, LP under pad 4; 3.2 deg slope; 0.78 m/s at 120 deg from downhill.
  const std::string path = Write(
      "d570.yaml", test::LunarStudyLandingYaml({.name = "d570",
                                                .slope_deg = 3.21959043931777,
                                                .vx_m_s = -0.38868591436571616,
                                                .vy_m_s = 0.6723119599012566,
                                                .roll_deg = 4.55408255858813,
                                                .pitch_deg = 3.22154457057323,
                                                .yaw_relative_to_slope_deg = 87.1448880945474,
                                                .soils = {"fjs1_cp", "fjs1_cp", "fjs1_cp", "fjs1_lp"},
                                                .simulation_extra = ""}));
  const LanderRun run = RunLanderScenario(LoadLanderScenario(path));
  const lander::LanderRunResult& r = run.result;
  ASSERT_TRUE(r.rest_time_s.has_value());
  EXPECT_FALSE(r.tipped_over);
  // Regression pins: this landing as RunLanderScenario runs it takes 1,121 solver steps and 21
  // events, and rests at 0.98 s (the reference model, 64 segments and rtol 1e-8: 0.997 s); a
  // capture offered at every crossing of the sink-rate root takes about 30,000 steps and 90 events.
  EXPECT_NEAR(*r.rest_time_s, 0.98, 0.03);
  EXPECT_LT(r.solver.steps, 3000);
  EXPECT_LT(r.events.size(), 60u);
}

}  // namespace
}  // namespace touchdown::scenario
