// A lander on a Bekker soil (rft/bekker_law.h): the scenario's ground takes the soil's own law, every
// pad's contact is the bekker law with the pad's b, and the landing on flat ground agrees with one
// pad with a quarter of the mass on the rig's Bekker response.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/catalog/catalog.h"
#include "rft/bekker_law.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::lander {
namespace {

TEST(LanderBekker, ScenarioOnABekkerSoilLandsLikeOneQuarterPad) {
  const scenario::LanderScenario sc = test::CoarseScenario("lander_lunar_bekker");
  ASSERT_EQ(sc.ground.law, rft::LawKind::kBekker);
  const scenario::LanderRun run = RunLanderScenario(sc);
  ASSERT_EQ(run.setup.terrain.soils.size(), 1u);
  const auto& law = dynamic_cast<const rft::BekkerLaw3D&>(*run.setup.terrain.soils[0].contact.law);
  EXPECT_DOUBLE_EQ(law.plate_b_m(), rft::BekkerPlateB(sc.lander.pad.body.surface));
  // One pad of the lander's (the catalogue's axisymmetric pad) on the rig, a quarter of the mass.
  drop::DropConditions c;
  c.mass_kg = sc.lander.total_mass_kg / 4.0;
  c.gravity_m_s2 = sc.gravity_m_s2;
  c.impact_speed_m_s = std::sqrt(2.0 * c.gravity_m_s2 * *sc.initial.drop_height_m);
  const drop::PadDrop single = drop::RunDrop(drop::ResolveDrop(sc.lander.pad, io::LoadSoil("lunar_nominal_bekker"), c));
  std::printf("[ bekker lander ] pad 1 %.4f mm, single pad (m/4) %.4f mm\n", run.result.final_penetration_m[0] * 1e3,
              single.result.final_penetration_m * 1e3);
  for (int leg = 0; leg < kNumLegs; ++leg)
    EXPECT_NEAR(run.result.final_penetration_m[leg] / single.result.final_penetration_m, 1.0, 0.03) << leg;
}

}  // namespace
}  // namespace touchdown::lander
