// Gravity scaling of a soil (rft/gravity_scaling.h) through a whole rig drop. An intruder set on
// the surface at rest sinks until the soil has absorbed the work of its weight,
//   m g d = zeta(g) (pi r^2 d^2 / 2 + 0.128 pi r d^3 / 3)      (flat bottom plus the side wall),
// so with lithostatic scaling (zeta proportional to g) the depth is the same at every gravity -
// what intrusion experiments in reduced gravity report - and without scaling it grows with g.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

namespace touchdown::drop {
namespace {

// The depth d > 0 of the energy balance above (bisection; the right side grows faster than the left).
double SettlingDepthClosedForm(double m, double g, double zeta_at_g, double r) {
  const double pi = std::numbers::pi;
  const auto excess = [&](double d) { return zeta_at_g * (pi * r * r * d / 2 + 0.128 * pi * r * d * d / 3) - m * g; };
  double lo = 1e-9, hi = 1.0;
  for (int i = 0; i < 200; ++i) (excess(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

double SettlingDepth(const rft::SoilParameters& soil, double gravity_m_s2) {
  DropConditions c;
  c.impact_speed_m_s = 0.0;
  c.gravity_m_s2 = gravity_m_s2;
  return RunDrop(ResolveDrop(io::LoadPad("flat"), soil, c)).result.final_penetration_m;
}

TEST(GravityScalingDrop, LithostaticSettlingDepthIsTheSameAtEveryGravity) {
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  ASSERT_EQ(soil.gravity_scaling, rft::GravityScaling::kLithostatic);
  // The shipped soil, dynamic term included: from rest the speeds scale as sqrt(g d), so the
  // term's lambda rho v^2 scales with g like the weight and zeta, and the depth stays the same.
  ASSERT_TRUE(soil.dynamic_term);
  EXPECT_NEAR(SettlingDepth(soil, 1.62), SettlingDepth(soil, 9.81), 1e-5 * SettlingDepth(soil, 9.81));
  // The closed form is quasi-static.
  soil.dynamic_term = false;
  const double earth = SettlingDepth(soil, 9.81), moon = SettlingDepth(soil, 1.62);
  const io::PadSpec pad = io::LoadPad("flat");
  const double closed = SettlingDepthClosedForm(pad.mass_kg, 9.81, soil.ZetaAtGravity(9.81), pad.profile.radius_m());
  EXPECT_NEAR(earth, closed, 1e-5 * closed);
  EXPECT_NEAR(moon, earth, 1e-5 * earth);
}

TEST(GravityScalingDrop, WithoutScalingTheSettlingDepthFollowsGravity) {
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  soil.dynamic_term = false;  // the closed form is quasi-static
  soil.gravity_scaling = rft::GravityScaling::kNone;
  const io::PadSpec pad = io::LoadPad("flat");
  const double moon = SettlingDepth(soil, 1.62);
  const double closed = SettlingDepthClosedForm(pad.mass_kg, 1.62, soil.zeta_N_m3, pad.profile.radius_m());
  EXPECT_NEAR(moon, closed, 1e-5 * closed);
  EXPECT_LT(moon, 0.2 * SettlingDepth(soil, 9.81));  // about g_moon / g_earth = 0.165 as deep
}

}  // namespace
}  // namespace touchdown::drop
