// Uehara / Ambroso's penetration-depth law: its length against a hand evaluation, its depth
// against cubics with known roots (both branches of the closed form) and against the law itself.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "drop_tests/validation/shallow_impact_depth.h"

namespace touchdown::validation {
namespace {

// rho_b = rho_g and D = 1 m leave L = c / mu.
ShallowImpactParameters UnitSphere(double prefactor, double mu) { return {prefactor, mu, 2000.0, 2000.0, 1.0}; }

TEST(ShallowImpactLaw, LengthOfKatsuragiDurianSphereAndBeadsMatchesAHandEvaluation) {
  // 0.14 / 0.45 x sqrt(8065.036222688207 / 1520) x 0.0254^(2/3): the 69.2 g, 25.4 mm steel sphere
  // (density 0.0692 / (4/3 pi 0.0127^3)) in the 1520 kg/m^3 glass beads, mu = 0.45; evaluated by hand
  // (Python, double precision) as 0.061923101460596264 m^(2/3).
  const double rho_b = 0.0692 / (4.0 / 3.0 * std::acos(-1.0) * 0.0127 * 0.0127 * 0.0127);
  const double length = ShallowImpactLength({0.14, 0.45, rho_b, 1520.0, 0.0254});
  EXPECT_NEAR(length, 0.061923101460596264, 1e-12 * length);
  // Released touching the surface, d = L^(3/2): 15.409 mm.
  EXPECT_NEAR(ShallowImpactDepth({0.14, 0.45, rho_b, 1520.0, 0.0254}, 0.0), std::pow(length, 1.5), 1e-12);
}

TEST(ShallowImpactLaw, DepthIsTheRootOfCubicsWithKnownRoots) {
  // L = 0.5: d = 1 solves d^3 = L^3 (h + d) for h = 7 (one real root, Cardano's branch).
  EXPECT_NEAR(ShallowImpactDepth(UnitSphere(0.25, 0.5), 7.0), 1.0, 1e-12);
  // L = 1: d = 1.1 solves d^3 - d = h for h = 0.231 (three real roots, the trigonometric branch).
  EXPECT_NEAR(ShallowImpactDepth(UnitSphere(0.5, 0.5), 0.231), 1.1, 1e-12);
  // L = 1, h = 6: d = 2.
  EXPECT_NEAR(ShallowImpactDepth(UnitSphere(0.5, 0.5), 6.0), 2.0, 1e-12);
}

TEST(ShallowImpactLaw, DepthSatisfiesTheLawAtEveryHeight) {
  const ShallowImpactParameters kd{0.14, 0.45, 8065.036222688207, 1520.0, 0.0254};
  const double length = ShallowImpactLength(kd);
  double previous = 0.0;
  for (const double h : {0.0, 0.001, 0.01, 0.0247, 0.03, 0.1, 0.3, 1.0, 10.0}) {
    const double d = ShallowImpactDepth(kd, h);
    EXPECT_NEAR(d, length * std::cbrt(h + d), 1e-12 * d) << h;
    EXPECT_GT(d, previous) << h;
    previous = d;
  }
}

TEST(ShallowImpactLaw, RefusesNonPhysicalInputs) {
  EXPECT_THROW(ShallowImpactLength({0.14, 0.0, 8000.0, 1500.0, 0.0254}), std::invalid_argument);
  EXPECT_THROW(ShallowImpactLength({0.14, 0.45, 8000.0, 0.0, 0.0254}), std::invalid_argument);
  EXPECT_THROW(ShallowImpactDepth({0.14, 0.45, 8000.0, 1500.0, 0.0254}, -0.01), std::invalid_argument);
}

}  // namespace
}  // namespace touchdown::validation
