// The two forms of added mass (rft/entrained_mass.h) against their closed forms: the plug's mass
// and rate on a flat footprint and on one growing with depth (a cone pad), the plug as the cone
// with its formation length a replaced by d_f, both forms together, and the factory's load-time
// checks of c_p.
#include "rft/entrained_mass.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::rft {
namespace {

constexpr double kPi = std::numbers::pi;

// A flat pad of radius a: the footprint is whole at first contact, so the plug grows linearly to
// c_p rho (pi/3) a^3 over d_f at the rate m_p v / d_f, then stays.
TEST(EntrainedPlug, FlatFootprintClosedForm) {
  const double rho = 1600.0, a = 0.05, A = kPi * a * a, d_f = 1e-3, v = 1.3;
  const double m_p = rho * kPi / 3 * a * a * a;
  for (const double d : {1e-5, 4e-4, 9.99e-4}) {
    const EntrainedMass e = EntrainedPlug(rho, d_f, d, v, A, 0.0);
    EXPECT_NEAR(e.mass_kg, m_p * d / d_f, 1e-14 * m_p) << d;
    EXPECT_NEAR(e.rate_kg_s, m_p * v / d_f, 1e-12 * m_p * v / d_f) << d;
  }
  for (const double d : {1e-3, 0.004, 0.2}) {
    const EntrainedMass e = EntrainedPlug(rho, d_f, d, v, A, 0.0);
    EXPECT_NEAR(e.mass_kg, m_p, 1e-14 * m_p) << d;
    EXPECT_EQ(e.rate_kg_s, 0.0) << d;
  }
  EXPECT_EQ(EntrainedPlug(rho, d_f, 0.0, v, A, 0.0).mass_kg, 0.0);
  EXPECT_EQ(EntrainedPlug(rho, d_f, -1e-3, v, A, 0.0).rate_kg_s, 0.0);
  EXPECT_EQ(EntrainedPlug(0.0, d_f, 0.01, v, A, 0.0).mass_kg, 0.0);
  // The plug is the cone with its formation length a replaced by d_f: with d_f = a they agree.
  for (const double d : {0.01, 0.03, 0.08}) {
    const EntrainedMass cone = EntrainedCone(rho, d, v, A, 0.0), plug = EntrainedPlug(rho, a, d, v, A, 0.0);
    EXPECT_NEAR(plug.mass_kg, cone.mass_kg, 1e-14 * m_p) << d;
    EXPECT_NEAR(plug.rate_kg_s, cone.rate_kg_s, 1e-12 * m_p * v / a) << d;
  }
}

// A cone pad of half-angle theta moving down at v: a(d) = d tan(theta), A = pi a^2, A' = 2 pi a
// tan(theta) v. Before d_f: m = (pi rho / 3) tan^3(theta) d^4 / d_f, so dm/dt = 4 m v / d; after:
// m = (pi rho / 3) tan^3(theta) d^3, dm/dt = 3 m v / d.
TEST(EntrainedPlug, GrowingFootprintClosedForm) {
  const double rho = 1500.0, d_f = 1e-3, v = 0.9, k = std::tan(0.6);
  for (const double d : {2e-4, 7e-4, 2e-3, 0.02}) {
    const double a = k * d;
    const EntrainedMass e = EntrainedPlug(rho, d_f, d, v, kPi * a * a, 2 * kPi * a * k * v);
    const double whole = rho * kPi / 3 * a * a * a;
    const double m = d < d_f ? whole * d / d_f : whole;
    EXPECT_NEAR(e.mass_kg, m, 1e-13 * m) << d;
    EXPECT_NEAR(e.rate_kg_s, (d < d_f ? 4.0 : 3.0) * m * v / d, 1e-12 * m * v / d) << d;
  }
}

// Both forms add; with no plug the sum is the cone to the bit (an absent plug changes nothing).
TEST(EntrainedPlug, GrainsAreConePlusPlug) {
  const double A = kPi * 0.04 * 0.04, d = 0.0006, v = 0.7, A_dot = 0.01;
  PadLevelTerms t;
  t.added_mass_density_kg_m3 = 800.0;
  const EntrainedMass cone = EntrainedCone(800.0, d, v, A, A_dot), alone = EntrainedGrains(t, d, v, A, A_dot);
  EXPECT_EQ(alone.mass_kg, cone.mass_kg);
  EXPECT_EQ(alone.rate_kg_s, cone.rate_kg_s);
  t.plug_density_kg_m3 = 400.0;
  EXPECT_TRUE(t.has_added_mass());
  const EntrainedMass plug = EntrainedPlug(400.0, kPlugFormationDepthM, d, v, A, A_dot);
  const EntrainedMass both = EntrainedGrains(t, d, v, A, A_dot);
  EXPECT_EQ(both.mass_kg, cone.mass_kg + plug.mass_kg);
  EXPECT_EQ(both.rate_kg_s, cone.rate_kg_s + plug.rate_kg_s);
  t.added_mass_density_kg_m3 = 0.0;
  EXPECT_TRUE(t.has_added_mass());  // the plug alone: the contact must report the footprint
}

// c_p is checked at load time like c_a: finite, non-negative, and the soil must state its density.
TEST(EntrainedPlug, FactoryChecksAndSetsIt) {
  SoilParameters soil;
  soil.name = "test";
  soil.zeta_N_m3 = 2.0e6;
  soil.bulk_density_kg_m3 = 1600.0;
  EffectTerms t;
  t.added_mass_plug_cp = 0.5;
  const SoilContactModel model = MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t);
  EXPECT_EQ(model.name(), "li2013+added_mass_plug");
  EXPECT_EQ(model.pad_terms.plug_density_kg_m3, 800.0);
  EXPECT_EQ(model.pad_terms.added_mass_density_kg_m3, 0.0);
  EXPECT_TRUE(t.NeedsDensity());
  t.added_mass_ca = 1.0;
  EXPECT_EQ(MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t).name(), "li2013+added_mass+added_mass_plug");
  for (const double bad : {-0.1, std::nan(""), std::numeric_limits<double>::infinity()}) {
    t.added_mass_plug_cp = bad;
    EXPECT_THROW(MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t), InputError) << bad;
  }
  t.added_mass_plug_cp = 0.5;
  t.added_mass_ca = 0.0;
  soil.bulk_density_kg_m3 = 0.0;
  EXPECT_THROW(MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t), InputError);
}

}  // namespace
}  // namespace touchdown::rft
