// Leg placement (lander/multibody/leg_placement.h): the joints and hips on their circles, pads
// clockwise from pad 1 front-left, the body's CoM from the whole lander's CoG; and an input that
// does not fit comes back as its field and the reason, for the loader to word.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "fixtures/paper_lander.h"
#include "lander/multibody/leg_placement.h"

namespace touchdown::lander {
namespace {

const LegLayout kLayout{/*joint_radius_m=*/0.15, /*hip_radius_m=*/0.05, /*hip_height_m=*/0.12};

TEST(LegPlacement, PlacesJointsAndHipsOnTheirCirclesAboutTheBodyCoM) {
  const geom::PadBody pad = test::LanderPad();
  const double total = 4.3, cog = 0.10;
  const auto placed = PlaceLegs(pad, total, cog, kLayout);
  ASSERT_TRUE(std::holds_alternative<LegPlacement>(placed));
  const LegPlacement& p = std::get<LegPlacement>(placed);
  EXPECT_DOUBLE_EQ(p.body_mass_kg, total - kNumLegs * pad.mass_kg);
  // The whole lander's CoM (body at the origin, pads' CoMs com_B above their joints) stands cog
  // above the pad bottoms, which lie lowest_z_B below the joints.
  double moment = 0.0;
  for (int i = 0; i < kNumLegs; ++i) moment += pad.mass_kg * (p.joint_B[i].z() + pad.com_B.z());
  const double com_z = moment / total;
  EXPECT_NEAR(com_z - (p.joint_B[0].z() + pad.lowest_z_B), cog, 1e-12);
  for (int i = 0; i < kNumLegs; ++i) {
    EXPECT_NEAR(p.joint_B[i].head<2>().norm(), kLayout.joint_radius_m, 1e-12);
    EXPECT_NEAR(p.hip_B[i].head<2>().norm(), kLayout.hip_radius_m, 1e-12);
    EXPECT_NEAR(p.hip_B[i].z() - (p.joint_B[i].z() + pad.lowest_z_B), kLayout.hip_height_m, 1e-12);
  }
  // Pad 1 front-left (+x, +y), then clockwise seen from above: front-right, rear-right, rear-left.
  EXPECT_GT(p.joint_B[0].x(), 0.0);
  EXPECT_GT(p.joint_B[0].y(), 0.0);
  EXPECT_GT(p.joint_B[1].x(), 0.0);
  EXPECT_LT(p.joint_B[1].y(), 0.0);
  EXPECT_LT(p.joint_B[2].x(), 0.0);
  EXPECT_LT(p.joint_B[2].y(), 0.0);
  EXPECT_LT(p.joint_B[3].x(), 0.0);
  EXPECT_GT(p.joint_B[3].y(), 0.0);
}

LegPlacementError ErrorOf(const std::variant<LegPlacement, LegPlacementError>& placed) {
  EXPECT_TRUE(std::holds_alternative<LegPlacementError>(placed));
  return std::holds_alternative<LegPlacementError>(placed) ? std::get<LegPlacementError>(placed) : LegPlacementError{};
}

TEST(LegPlacement, PadsAsHeavyAsTheLanderNameTheTotalMass) {
  const geom::PadBody pad = test::LanderPad();
  const LegPlacementError e = ErrorOf(PlaceLegs(pad, kNumLegs * pad.mass_kg, 0.10, kLayout));
  EXPECT_EQ(e.field, LegPlacementError::Field::kTotalMass);
  EXPECT_EQ(e.reason, "must exceed the four pads' mass");
}

TEST(LegPlacement, ACoGThatPutsTheBodyBelowTheJointsNamesTheCoGHeight) {
  const geom::PadBody pad = test::LanderPad();
  const LegPlacementError e = ErrorOf(PlaceLegs(pad, 4.3, 1e-4, kLayout));
  EXPECT_EQ(e.field, LegPlacementError::Field::kCogHeight);
  EXPECT_EQ(e.reason, "puts the body's centre of mass below the joints");
}

TEST(LegPlacement, HipsBelowTheJointsNameTheHipHeight) {
  const geom::PadBody pad = test::LanderPad();
  LegLayout low = kLayout;
  low.hip_height_m = -pad.lowest_z_B;  // at the joint centres: not above them
  const LegPlacementError e = ErrorOf(PlaceLegs(pad, 4.3, 0.10, low));
  EXPECT_EQ(e.field, LegPlacementError::Field::kHipHeight);
  EXPECT_EQ(e.reason, "must be above the ball-joint centres");
}

}  // namespace
}  // namespace touchdown::lander
