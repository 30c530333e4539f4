// The one contact-model factory: a model file's zeta (at its own reference gravity) and
// dynamic_lambda reach the 3D law, gas_cushion acts on beds in air only, the law defaults to the
// soil's own, and mistakes are refused.
#include "drop_tests/model/contact_model.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "drop_tests/catalog/catalog.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d.h"

namespace {

using namespace touchdown;
using model::ContactModelRequest;
using model::MakeContactModel;

const Eigen::Vector3d kContactDown(0.0, 0.0, -1.0);

double ContactVerticalStressPerDepth(const rft::SoilContactModel& m) { return m.law->StressPerDepth(kContactDown, kContactDown).z(); }

TEST(ContactModel, ModelZetaAtItsReferenceGravityReachesTheLaw) {
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");  // reference gravity 9.81
  model::ModelFile m;
  m.name = "lab";
  model::SoilOverride o;
  o.zeta_N_m3 = 3.0e6;
  o.reference_gravity_m_s2 = 1.62;
  m.soils[soil.name] = o;
  // Li 2013's stress per depth is linear in zeta, and zeta at the run's gravity is the model's
  // when the run is at the model's reference gravity.
  rft::SoilParameters stated = soil;
  stated.zeta_N_m3 = 3.0e6;
  stated.reference_gravity_m_s2 = 1.62;
  const double with_model = ContactVerticalStressPerDepth(
      MakeContactModel({.law = rft::LawKind::kLi2013, .soil = soil, .gravity_m_s2 = 1.62, .model = &m}));
  const double expected = ContactVerticalStressPerDepth(
      MakeContactModel({.law = rft::LawKind::kLi2013, .soil = stated, .gravity_m_s2 = 1.62}));
  EXPECT_NEAR(with_model, expected, 1e-12 * std::abs(expected));
  // At twice the gravity, twice the stress.
  const double doubled = ContactVerticalStressPerDepth(
      MakeContactModel({.law = rft::LawKind::kLi2013, .soil = soil, .gravity_m_s2 = 3.24, .model = &m}));
  EXPECT_NEAR(doubled, 2.0 * expected, 1e-12 * std::abs(expected));
}

TEST(ContactModel, ModelDynamicLambdaReplacesTheSoils) {
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");  // dynamic term on, lambda 1.1
  ASSERT_TRUE(soil.dynamic_term);
  model::ModelFile m;
  model::SoilOverride o;
  o.zeta_N_m3 = soil.zeta_N_m3;
  o.reference_gravity_m_s2 = soil.reference_gravity_m_s2;
  o.dynamic_lambda = 2.0;
  m.soils[soil.name] = o;
  const double rho_c = soil.dynamic_density_kg_m3 > 0.0 ? soil.dynamic_density_kg_m3 : soil.bulk_density_kg_m3;
  // lambda rho_c (v.n)^2 against n, at v = 2 m/s straight down.
  const rft::SoilContactModel c = MakeContactModel({.soil = soil, .gravity_m_s2 = 9.81, .model = &m});
  EXPECT_NEAR(c.law->DynamicStress(kContactDown, 2.0 * kContactDown).z(), 2.0 * rho_c * 4.0, 1e-9);
}

TEST(ContactModel, GasCushionActsOnBedsInAirOnly) {
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  rft::EffectTerms gas;
  gas.gas_chi = 0.3;
  gas.gas_c_N_s_m3 = 5000.0;
  EXPECT_EQ(MakeContactModel({.soil = soil, .gravity_m_s2 = 9.81, .effects = gas}).name(), "li2013+dynamic");
  soil.atmosphere = rft::Atmosphere::kAir;
  EXPECT_EQ(MakeContactModel({.soil = soil, .gravity_m_s2 = 9.81, .effects = gas}).name(),
            "li2013+dynamic+gas_cushion");
}

TEST(ContactModel, LawDefaultsToTheSoilsOwn) {
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  soil.rft_law_3d = rft::LawKind::kAgarwal2023;
  EXPECT_EQ(MakeContactModel({.soil = soil, .gravity_m_s2 = 9.81}).law->kind(), rft::LawKind::kAgarwal2023);
  EXPECT_EQ(MakeContactModel({.law = rft::LawKind::kLi2013, .soil = soil, .gravity_m_s2 = 9.81}).law->kind(),
            rft::LawKind::kLi2013);
}

TEST(ContactModel, RefusesMistakes) {
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  rft::EffectTerms drag;
  drag.inertial_lambda = 1.0;
  model::ModelFile m;
  m.source = "lab_model.yaml";
  // Terms beside a model file: a bug of the caller (the model's terms are the run's).
  EXPECT_THROW(MakeContactModel({.soil = soil, .gravity_m_s2 = 9.81, .model = &m, .effects = drag}),
               std::invalid_argument);
  // inertial_drag needs the bulk density; the error names where the term came from.
  soil.bulk_density_kg_m3 = 0.0;
  soil.dynamic_term = false;
  try {
    MakeContactModel({.soil = soil, .gravity_m_s2 = 9.81, .effects = drag, .effects_source = "--effect"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--effect"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bulk_density_kg_m3"), std::string::npos) << e.what();
  }
}

}  // namespace
