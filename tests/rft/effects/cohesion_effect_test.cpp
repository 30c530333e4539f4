// cohesion (rft/effects/cohesion_effect.cpp) against its closed forms: the rig's N_c c I_1(d) and
// the element stress -N_c c n, N_c = pi + 2; the library's generic checks (neutral values, 3D
// against rig, every command) are in tests/apps/registered_effects_test.cpp.
#include <gtest/gtest.h>

#include <numbers>

#include "rft/effects/effect_definition.h"

namespace touchdown::rft {
namespace {

const EffectDefinition& Cohesion() {
  for (const EffectDefinition& e : RegisteredEffects())
    if (e.id == "cohesion") return e;
  throw std::logic_error("cohesion is not registered");
}

constexpr double kNc = std::numbers::pi + 2.0;

TEST(CohesionEffect, OneParameterInKilopascalsFromZero) {
  const EffectDefinition& e = Cohesion();
  ASSERT_EQ(e.parameters.size(), 1u);
  EXPECT_EQ(e.parameters[0].key, "c_kPa");
  EXPECT_EQ(e.parameters[0].file_to_si, 1e3);
  EXPECT_EQ(e.parameters[0].neutral, 0.0);
  EXPECT_EQ(e.parameters[0].lower, 0.0);
  EXPECT_TRUE(e.parameters[0].RangeProblem(-1.0).find("must be in [0, 100]") != std::string::npos);
  EXPECT_TRUE(e.parameters[0].RangeProblem(1e3).empty());  // the lunar regolith's 1 kPa
  EXPECT_FALSE(e.air_only);
  EXPECT_FALSE(e.needs_bulk_density);
}

// The rig: a flat pad of footprint A = I_1 carries N_c c A from the first instant of contact, at
// rest too (the static capacity), whatever its speed; nothing before touchdown.
TEST(CohesionEffect, RigFormIsTheBearingStressOnTheFootprint) {
  const EffectDefinition& e = Cohesion();
  const double c = 600.0;  // Pa
  const double area = std::numbers::pi * 0.05 * 0.05;
  for (double v : {0.0, 0.3, 2.0}) {
    const RigPoint p{0.004, v, area, 0.7 * area, 0.5 * area, 1600.0};
    EXPECT_DOUBLE_EQ(e.rig_force_N(&c, p), kNc * c * area) << v;
  }
  EXPECT_EQ(e.rig_force_N(&c, RigPoint{0.0, 1.0, area, area, area, 1600.0}), 0.0);
  EXPECT_EQ(e.rig_force_N(&c, RigPoint{-0.001, 1.0, area, area, area, 1600.0}), 0.0);
  const double none = 0.0;
  EXPECT_EQ(e.rig_force_N(&none, RigPoint{0.004, 1.0, area, area, area, 1600.0}), 0.0);
}

// The 3D form: -N_c c n on any element the contact hands it, whatever the speed (the contact
// fades faces turning away); a horizontal plate moving down is pushed up by N_c c.
TEST(CohesionEffect, ElementStressIsNormalAndIndependentOfSpeed) {
  const EffectDefinition& e = Cohesion();
  const double c = 900.0;
  const Eigen::Vector3d down(0, 0, -1);
  for (double v : {1e-3, 1.0, 5.0}) {
    const Eigen::Vector3d s = e.element_stress_Pa(&c, 1500.0, down, Eigen::Vector3d(0, 0, -v));
    EXPECT_DOUBLE_EQ(s.z(), kNc * c) << v;
    EXPECT_EQ(s.x(), 0.0);
    EXPECT_EQ(s.y(), 0.0);
  }
  const Eigen::Vector3d n = Eigen::Vector3d(1, 0, -1).normalized();
  const Eigen::Vector3d s = e.element_stress_Pa(&c, 1500.0, n, Eigen::Vector3d(0.3, 0, -1));
  EXPECT_NEAR((s + kNc * c * n).norm(), 0.0, 1e-12 * kNc * c);
}

}  // namespace
}  // namespace touchdown::rft
