// Li, Zhang & Goldman 2013 generic stress law: published check values, the mirror rule and
// the periodicity of a plate.
#include "rft/li2013.h"

#include <gtest/gtest.h>

#include <numbers>

#include "rft/soil.h"
#include "rft/stress_law.h"

namespace touchdown::rft {
namespace {


TEST(RftLi2013, HorizontalPlatePushedDownIsExactlyOne) {
  // alpha_z(0, pi/2) = A00 + A10 + B11 + B01 + B-11 = 1.000: zeta is the plate's stress per depth.
  EXPECT_NEAR(Li2013Alpha(0.0, std::numbers::pi / 2).z, 1.0, 1e-12);
}

TEST(RftLi2013, PublishedCheckValues) {
  EXPECT_NEAR(Li2013Alpha(std::numbers::pi / 4, std::numbers::pi / 2).z, 0.564, 5e-4);
  EXPECT_NEAR(Li2013Alpha(std::numbers::pi / 2, std::numbers::pi / 2).z, 0.128, 5e-4);
  EXPECT_NEAR(Li2013Alpha(0.0, -std::numbers::pi / 2).z, -0.25, 5e-4);
  EXPECT_NEAR(Li2013Alpha(0.0, std::numbers::pi / 2).x, 0.0, 1e-12);
  EXPECT_NEAR(Li2013Alpha(0.0, -std::numbers::pi / 2).x, 0.0, 1e-12);
}

TEST(RftLi2013, VerticalIntrusionIsEvenInAttackAngle) {
  for (double b = -std::numbers::pi / 2; b <= std::numbers::pi / 2; b += 0.1)
    EXPECT_NEAR(Li2013Alpha(b, std::numbers::pi / 2).z, Li2013Alpha(-b, std::numbers::pi / 2).z, 1e-14) << "beta " << b;
}

class RftLi2013Mirror : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(RftLi2013Mirror, MirrorIdentitiesHold) {
  const auto [beta, gamma] = GetParam();  // gamma in (pi/2, pi]: outside the fitted range
  const Alpha2 a = Li2013Alpha(beta, gamma);
  const Alpha2 mirrored = Li2013FitRaw(Li2013Coefficients{}, -beta, std::numbers::pi - gamma);
  EXPECT_NEAR(a.z, mirrored.z, 1e-14);
  EXPECT_NEAR(a.x, -mirrored.x, 1e-14);
  // And the law is the same however the angle is written.
  const Alpha2 wrapped = Li2013Alpha(beta, gamma - 2 * std::numbers::pi);
  EXPECT_NEAR(a.z, wrapped.z, 1e-12);
  EXPECT_NEAR(a.x, wrapped.x, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AnglesBeyondHalfPi, RftLi2013Mirror,
                         ::testing::Values(std::pair{0.0, 2.0}, std::pair{0.3, 2.5}, std::pair{-0.7, 3.0},
                                           std::pair{1.2, std::numbers::pi}, std::pair{-1.5, 1.9}));

TEST(RftLi2013, MirrorRuleIsContinuousAtHalfPi) {
  for (double b = -1.5; b <= 1.5; b += 0.25) {
    const Alpha2 below = Li2013Alpha(b, std::numbers::pi / 2 - 1e-9), above = Li2013Alpha(b, std::numbers::pi / 2 + 1e-9);
    EXPECT_NEAR(below.z, above.z, 1e-7) << "beta " << b;
  }
}

TEST(RftLi2013, HorizontalMotionMirrorsHorizontalStress) {
  // Moving along -x is the mirror image of moving along +x: alpha_x flips, alpha_z stays.
  for (double b : {-0.8, -0.2, 0.0, 0.4, 1.1}) {
    const Alpha2 forward = Li2013Alpha(b, 0.3);
    const Alpha2 backward = Li2013Alpha(-b, std::numbers::pi - 0.3);
    EXPECT_NEAR(forward.z, backward.z, 1e-14);
    EXPECT_NEAR(forward.x, -backward.x, 1e-14);
  }
}

TEST(RftLi2013, PlateIsPeriodicInHalfTurns) {
  for (double g : {-1.0, 0.2, 1.4})
    EXPECT_NEAR(Li2013Alpha(0.3, g).z, Li2013Alpha(0.3 + std::numbers::pi, g).z, 1e-12);
}

TEST(RftLi2013, LawInterfaceMatchesFreeFunction) {
  const Li2013Law law;
  EXPECT_EQ(law.name(), "li2013");
  EXPECT_DOUBLE_EQ(law.Alpha(0.4, 1.0).z, Li2013Alpha(0.4, 1.0).z);
  EXPECT_DOUBLE_EQ(law.Alpha(0.4, 1.0).x, Li2013Alpha(0.4, 1.0).x);
}

TEST(RftSoil, AgarwalScalingAndGravity) {
  // xi = rho g (894 mu^3 - 386 mu^2 + 89 mu); for mu = 0.5: 111.75 - 96.5 + 44.5 = 59.75.
  EXPECT_NEAR(AgarwalScalingXi(1500.0, 9.81, 0.5), 1500.0 * 9.81 * 59.75, 1e-6);
  SoilParameters s;
  s.zeta_N_m3 = 2e6;
  s.reference_gravity_m_s2 = 9.81;
  EXPECT_NEAR(s.ZetaAtGravity(1.62), 2e6 * 1.62 / 9.81, 1e-6);
  // A zeta given at lunar gravity: the soil's reference zeta is scaled up to 9.81.
  s.SetZetaAtGravity(0.5e6, 1.62);
  EXPECT_NEAR(s.zeta_N_m3, 0.5e6 * 9.81 / 1.62, 1e-6);
  EXPECT_NEAR(s.ZetaAtGravity(1.62), 0.5e6, 1e-6);
}

TEST(RftSoil, WithoutGravityScalingZetaIsTheSameAtEveryGravity) {
  SoilParameters s;
  s.zeta_N_m3 = 2e6;
  s.gravity_scaling = GravityScaling::kNone;
  EXPECT_EQ(s.ZetaAtGravity(1.62), 2e6);
  EXPECT_EQ(s.ZetaAtGravity(9.81), 2e6);
  s.SetZetaAtGravity(0.5e6, 1.62);
  EXPECT_EQ(s.zeta_N_m3, 0.5e6);
  EXPECT_EQ(ParseGravityScaling("lithostatic"), GravityScaling::kLithostatic);
  EXPECT_EQ(ParseGravityScaling("none"), GravityScaling::kNone);
  EXPECT_FALSE(ParseGravityScaling("linear").has_value());
  EXPECT_STREQ(GravityScalingName(GravityScaling::kNone), "none");
}

}  // namespace
}  // namespace touchdown::rft
