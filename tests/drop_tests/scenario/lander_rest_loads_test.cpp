// The pads' loads across the rest event of the paper's case B (the loads figure draws them): the
// forces before it are the soil's RFT forces on a lander that rebounds, after it the holds'
// reactions. Why the figure shows a step there and a leg in tension before it, in numbers:
//   - from about 160.5 ms the lander rebounds (pad 1, on the stiffer soil, rises first, at up to
//     5 cm/s; the body just after, at up to 2 cm/s) and the soil resists the pads' withdrawal
//     (RFT resists motion in any direction, at any speed): a leg pulls only while its pad rises,
//     by up to 4 N on pad 1 and 8 N on pads 2 and 4 after pad 3's capture, the model's answer, not
//     rounding;
//   - at the rest instant those forces hold up a small part of the weight (the body falls back at
//     nearly g), while the holds' reactions after it carry all of it, to rounding: the step is the
//     switch from a rebounding lander's soil forces to a standing lander's support.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>

#include "drop_tests/scenario/lander_leg_load.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::scenario {
namespace {

Eigen::Vector3d TotalPadForce(const lander::LanderSample& s) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& pad : s.pad_force_W) f += pad;
  return f;
}

TEST(LanderRestLoads, CaseBLegsPullWhileTheBodyReboundsAndTheHoldsCarryTheWeightAfterRest) {
  const LanderScenario scenario = LoadLanderScenario(test::ScenarioPath("lander_case_B"));
  const LanderRun run = RunLanderScenario(scenario);
  ASSERT_TRUE(run.result.rest_time_s.has_value());
  const double rest = *run.result.rest_time_s;
  const double weight = scenario.lander.total_mass_kg * scenario.gravity_m_s2;
  const auto& trace = run.result.trace;
  // The sample repeated at the rest instant: the first holds the state before the switch.
  const auto first_at_rest = std::find_if(trace.begin(), trace.end(), [&](const auto& s) { return s.t_s == rest; });
  ASSERT_NE(first_at_rest, trace.end());
  ASSERT_NE(first_at_rest + 1, trace.end());
  ASSERT_EQ((first_at_rest + 1)->t_s, rest) << "the rest instant is sampled before and after the switch";

  double least_leg_force = INFINITY;
  bool rising_when_pulling = true;
  for (auto s = trace.begin(); s != first_at_rest + 1; ++s)
    for (int leg = 0; leg < lander::kNumLegs; ++leg) {
      const double f = LegAxialForce(scenario.lander, *s, leg);
      least_leg_force = std::min(least_leg_force, f);
      if (f < -1e-6 * weight) rising_when_pulling &= s->v_WJ_W[leg].z() > 0.0;
    }
  EXPECT_LT(least_leg_force, -1.0) << "a leg in tension during the rebound, far above rounding";
  EXPECT_TRUE(rising_when_pulling) << "a leg pulls only while its pad rises";
  EXPECT_GT(first_at_rest->v_WB_W.z(), 0.0);
  EXPECT_LT(TotalPadForce(*first_at_rest).z(), 0.1 * weight) << "just before the switch the soil holds up little";

  for (auto s = first_at_rest + 1; s != trace.end(); ++s) {
    const Eigen::Vector3d total = TotalPadForce(*s);
    EXPECT_NEAR(total.z(), weight, 1e-9 * weight) << "t = " << s->t_s;
    EXPECT_NEAR(total.head<2>().norm(), 0.0, 1e-9 * weight) << "t = " << s->t_s;
    for (int leg = 0; leg < lander::kNumLegs; ++leg) EXPECT_GT(LegAxialForce(scenario.lander, *s, leg), 0.0);
  }
}

}  // namespace
}  // namespace touchdown::scenario
