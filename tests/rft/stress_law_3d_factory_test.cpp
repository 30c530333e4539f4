// MakeStressLaw3D: law selection, gravity scaling, the dynamic switch and input errors.
#include "rft/stress_law_3d_factory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rft/dynamic_term.h"
#include "rft/input_error.h"

namespace touchdown::rft {
namespace {

SoilParameters FactorySoil() {
  SoilParameters s;
  s.name = "test_soil";
  s.zeta_N_m3 = 3.48e6;
  s.reference_gravity_m_s2 = 9.81;
  s.bulk_density_kg_m3 = 1540.0;
  s.internal_friction_angle_rad = 37.0 * std::numbers::pi / 180;
  return s;
}

const Eigen::Vector3d kDown_W(0, 0, -1);

TEST(RftStressLawFactory, Li2013ScalesZetaWithGravity) {
  const auto law = MakeStressLaw3D(LawKind::kLi2013, FactorySoil(), 1.62);
  EXPECT_EQ(law->name(), "li2013");
  EXPECT_NEAR(law->StressPerDepth(kDown_W, kDown_W).z(), 3.48e6 * 1.62 / 9.81, 1e-6);
}

TEST(RftStressLawFactory, Agarwal2023UsesXiFromDensityAndFriction) {
  const SoilParameters s = FactorySoil();
  const auto law = MakeStressLaw3D(LawKind::kAgarwal2023, s, 9.81);
  EXPECT_EQ(law->name(), "agarwal2023");
  const double xi = AgarwalScalingXi(1540.0, 9.81, std::tan(s.internal_friction_angle_rad));
  EXPECT_NEAR(law->StressPerDepth(kDown_W, kDown_W).z(), xi, 1e-6 * xi);
}

TEST(RftStressLawFactory, DynamicTermIsSwitchedPerSoil) {
  SoilParameters s = FactorySoil();
  EXPECT_EQ(MakeSoilContactModel(LawKind::kLi2013, s, 9.81, {}).law->DynamicStress(kDown_W, kDown_W),
            Eigen::Vector3d::Zero());
  s.dynamic_term = true;
  s.dynamic_lambda = 2.0;
  // The quasi-static law alone; the soil's term comes in as an effect term, in every simulation.
  EXPECT_EQ(MakeStressLaw3D(LawKind::kLi2013, s, 9.81)->name(), "li2013");
  EXPECT_EQ(WithSoilDynamicTerm({}, s).inertial_lambda, 2.0);
  const auto law = MakeSoilContactModel(LawKind::kLi2013, s, 9.81, {}).law;
  EXPECT_EQ(law->name(), "li2013+dynamic");
  EXPECT_NEAR(law->DynamicStress(kDown_W, 3.0 * kDown_W).z(), 2.0 * 1540.0 * 9.0, 1e-9);  // rho_c = bulk density
  s.dynamic_density_kg_m3 = 2000.0;
  EXPECT_NEAR(MakeSoilContactModel(LawKind::kAgarwal2023, s, 9.81, {}).law->DynamicStress(kDown_W, kDown_W).z(),
              2.0 * 2000.0, 1e-9);
  // A model that states inertial_drag replaces the soil's term, even at lambda 0.
  EffectTerms stated;
  stated.inertial_replaces_soil = true;
  EXPECT_EQ(WithSoilDynamicTerm(stated, s).inertial_lambda, 0.0);
  EXPECT_EQ(MakeSoilContactModel(LawKind::kLi2013, s, 9.81, stated).law->name(), "li2013");
}

// A law says which kind it is, and a decorator says its inner law's: code that treats a law by
// its kind does not read its name.
TEST(RftStressLawFactory, EveryLawKnowsItsKindThroughItsDecorators) {
  SoilParameters s = FactorySoil();
  s.dynamic_term = true;
  s.dynamic_lambda = 2.0;
  EffectTerms damped;
  damped.damping_c_N_s_m3 = 1e3;
  for (const LawKind k : {LawKind::kLi2013, LawKind::kAgarwal2023}) {
    EXPECT_EQ(MakeStressLaw3D(k, s, 9.81)->kind(), k);
    const SoilContactModel m = MakeSoilContactModel(k, s, 9.81, damped);
    EXPECT_EQ(m.law->name(), std::string(LawKindName(k)) + "+dynamic+rate_damping");
    EXPECT_EQ(m.law->kind(), k);
  }
}

TEST(RftStressLawFactory, BadInputThrowsNamingSoilAndField) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  SoilParameters s = FactorySoil();
  EXPECT_EQ(message([&] { ParseLawKind("wong", "soil.yaml", "law"); }),
            "soil.yaml: law: unknown 3D stress law 'wong' (expected li2013, agarwal2023 or bekker)");
  for (const LawKind k : {LawKind::kLi2013, LawKind::kAgarwal2023})
    EXPECT_EQ(ParseLawKind(LawKindName(k), "", ""), k);
  EXPECT_EQ(LawKindName(LawKind::kAgarwal2023), "agarwal2023");
  s.bulk_density_kg_m3 = 0.0;
  EXPECT_NE(message([&] { MakeStressLaw3D(LawKind::kAgarwal2023, s, 9.81); }).find("bulk_density_kg_m3"),
            std::string::npos);
  EXPECT_NO_THROW(MakeStressLaw3D(LawKind::kLi2013, s, 9.81));  // li2013 needs only zeta
  s = FactorySoil();
  s.internal_friction_angle_rad = 0.0;
  EXPECT_NE(message([&] { MakeStressLaw3D(LawKind::kAgarwal2023, s, 9.81); }).find("internal_friction_angle"),
            std::string::npos);
  s = FactorySoil();
  s.zeta_N_m3 = 0.0;
  EXPECT_NE(message([&] { MakeStressLaw3D(LawKind::kLi2013, s, 9.81); }).find("zeta"), std::string::npos);
  EXPECT_THROW(MakeStressLaw3D(LawKind::kLi2013, FactorySoil(), -1.0), InputError);
  s = FactorySoil();
  s.dynamic_term = true;
  s.bulk_density_kg_m3 = 0.0;
  EXPECT_NE(message([&] { MakeSoilContactModel(LawKind::kLi2013, s, 9.81, {}); }).find("bulk_density_kg_m3"),
            std::string::npos);
}

}  // namespace
}  // namespace touchdown::rft
