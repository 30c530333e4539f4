// Soil files: every bundled soil, and one that uses every optional field, loaded, written with
// WriteSoil and loaded again give the same soil; a second write is the same text (a fixed point).
#include <gtest/gtest.h>

#include <fstream>

#include "drop_tests/catalog/catalog.h"
#include "tests/round_trip.h"

namespace touchdown::io {
namespace {

struct SoilRoundTrip : testing_scratch::ScratchDirTest {};

void ExpectSameSoil(const rft::SoilParameters& a, const rft::SoilParameters& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.atmosphere, b.atmosphere);
  // zeta and the friction angle go through N/cm^3 and degrees: equal to the last bits.
  EXPECT_DOUBLE_EQ(a.zeta_N_m3, b.zeta_N_m3);
  EXPECT_DOUBLE_EQ(a.internal_friction_angle_rad, b.internal_friction_angle_rad);
  EXPECT_EQ(a.reference_gravity_m_s2, b.reference_gravity_m_s2);
  EXPECT_EQ(a.bulk_density_kg_m3, b.bulk_density_kg_m3);
  EXPECT_EQ(a.surface_friction_coefficient, b.surface_friction_coefficient);
  EXPECT_EQ(a.dynamic_term, b.dynamic_term);
  EXPECT_EQ(a.dynamic_lambda, b.dynamic_lambda);
  EXPECT_EQ(a.dynamic_density_kg_m3, b.dynamic_density_kg_m3);
  EXPECT_EQ(a.rft_law_3d, b.rft_law_3d);
  EXPECT_EQ(a.gravity_scaling, b.gravity_scaling);
  // The bekker block goes through kN, kPa, degrees and mm.
  EXPECT_DOUBLE_EQ(a.bekker.n, b.bekker.n);
  EXPECT_DOUBLE_EQ(a.bekker.k_c_N_m_n1, b.bekker.k_c_N_m_n1);
  EXPECT_DOUBLE_EQ(a.bekker.k_phi_N_m_n2, b.bekker.k_phi_N_m_n2);
  EXPECT_DOUBLE_EQ(a.bekker.cohesion_Pa, b.bekker.cohesion_Pa);
  EXPECT_DOUBLE_EQ(a.bekker.friction_angle_rad, b.bekker.friction_angle_rad);
  EXPECT_DOUBLE_EQ(a.bekker.shear_modulus_K_m, b.bekker.shear_modulus_K_m);
}

void RoundTrip(const rft::SoilParameters& loaded, const std::string& first, const std::string& second) {
  testing_scratch::ExpectRoundTrip(
      loaded, first, second, [](const rft::SoilParameters& s, const std::string& path) { WriteSoil(s, path); },
      [](const std::string& path) { return LoadSoil(path); }, ExpectSameSoil);
}

TEST_F(SoilRoundTrip, BundledSoils) {
  for (const char* name : {"fjs1_lp", "fjs1_cp", "lunar_nominal_bekker", "soft_sand_bekker", "toyoura_bekker"}) {
    SCOPED_TRACE(name);
    RoundTrip(LoadSoil(name), Path(std::string(name) + "_1.yaml"), Path(std::string(name) + "_2.yaml"));
  }
}

TEST_F(SoilRoundTrip, EveryOptionalField) {
  std::ofstream(Path("full.yaml")) << "schema_version: 1\nname: lab_sand\natmosphere: air\nzeta_N_cm3: 2.37\n"
                                      "reference_gravity_m_s2: 1.62\nbulk_density_kg_m3: 1580\n"
                                      "internal_friction_angle_deg: 37.5\nmu_surf: 0.55\ndynamic_term: true\n"
                                      "dynamic_lambda: 1.7\ndynamic_density_kg_m3: 1600\ngravity_scaling: none\n";
  const rft::SoilParameters soil = LoadSoil(Path("full.yaml"));
  EXPECT_EQ(soil.gravity_scaling, rft::GravityScaling::kNone);
  EXPECT_EQ(soil.atmosphere, rft::Atmosphere::kAir);
  EXPECT_DOUBLE_EQ(soil.zeta_N_m3, 2.37e6);
  EXPECT_EQ(soil.reference_gravity_m_s2, 1.62);
  EXPECT_TRUE(soil.dynamic_term);
  EXPECT_EQ(soil.dynamic_density_kg_m3, 1600.0);
  RoundTrip(soil, Path("full_1.yaml"), Path("full_2.yaml"));
}

TEST_F(SoilRoundTrip, DerivedZetaIsWrittenAsANumber) {
  std::ofstream(Path("agarwal.yaml")) << "schema_version: 1\nzeta_N_cm3: agarwal2023\nbulk_density_kg_m3: 1500\n"
                                         "internal_friction_angle_deg: 35\n";
  const rft::SoilParameters soil = LoadSoil(Path("agarwal.yaml"));
  EXPECT_GT(soil.zeta_N_m3, 0.0);
  RoundTrip(soil, Path("agarwal_1.yaml"), Path("agarwal_2.yaml"));
  EXPECT_EQ(Slurp(Path("agarwal_1.yaml")).find("agarwal2023"), std::string::npos);
}

}  // namespace
}  // namespace touchdown::io
