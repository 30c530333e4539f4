// Bekker soil files (`law: bekker` with a `bekker:` block): the shipped soils in SI, and every bad
// block refused at load naming the file, the field and the value.
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "rft/input_error.h"
#include "tests/round_trip.h"

namespace touchdown::io {
namespace {

struct BekkerSoilFile : testing_scratch::ScratchDirTest {
  std::string Error(const std::string& text) {
    std::ofstream(Path("s.yaml")) << text;
    try {
      LoadSoil(Path("s.yaml"));
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(BekkerSoilFile, LunarNominalInSi) {
  const rft::SoilParameters s = LoadSoil("lunar_nominal_bekker");
  EXPECT_EQ(s.rft_law_3d, rft::LawKind::kBekker);
  EXPECT_EQ(s.zeta_N_m3, 0.0);
  EXPECT_EQ(s.bekker.n, 1.0);
  EXPECT_DOUBLE_EQ(s.bekker.k_c_N_m_n1, 1400.0);
  EXPECT_DOUBLE_EQ(s.bekker.k_phi_N_m_n2, 820e3);
  EXPECT_DOUBLE_EQ(s.bekker.cohesion_Pa, 170.0);
  EXPECT_DOUBLE_EQ(s.bekker.friction_angle_rad, 35.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(s.bekker.shear_modulus_K_m, 0.018);
  const rft::SoilParameters toyoura = LoadSoil("toyoura_bekker");
  EXPECT_EQ(toyoura.bekker.n, 0.63);
  EXPECT_EQ(toyoura.bekker.k_c_N_m_n1, 0.0);
  EXPECT_DOUBLE_EQ(toyoura.bekker.cohesion_Pa, 24.5);
}

TEST_F(BekkerSoilFile, BadBlocksNameFileFieldAndValue) {
  const std::string head = "schema_version: 1\nlaw: bekker\n";
  const std::string good = "  n: 1\n  k_c_kN_m_n1: 1.4\n  k_phi_kN_m_n2: 820\n  cohesion_kPa: 0.17\n"
                           "  friction_angle_deg: 35\n  shear_modulus_K_mm: 18\n";
  EXPECT_EQ(Error(head + "bekker:\n" + good), "no error");
  EXPECT_NE(Error(head).find("s.yaml: bekker: missing"), std::string::npos) << Error(head);
  std::string block = good;
  block.replace(block.find("n: 1"), 4, "n: -1");
  EXPECT_NE(Error(head + "bekker:\n" + block).find("bekker.n"), std::string::npos);
  block = good;
  block.replace(block.find("shear_modulus_K_mm: 18"), 22, "shear_modulus_K_mm: 0");
  EXPECT_NE(Error(head + "bekker:\n" + block).find("bekker.shear_modulus_K_mm"), std::string::npos);
  block = good;
  block.replace(block.find("friction_angle_deg: 35"), 22, "friction_angle_deg: 95");
  EXPECT_NE(Error(head + "bekker:\n" + block).find("bekker.friction_angle_deg: must be below 90"), std::string::npos);
  EXPECT_NE(Error(head + "bekker:\n" + good + "  k_phi_kN_m_n: 3\n").find("k_phi_kN_m_n"), std::string::npos);
  EXPECT_NE(Error("schema_version: 1\nlaw: wong\nzeta_N_cm3: 1\n").find("s.yaml: law:"), std::string::npos);
  // An RFT soil still needs its zeta; a Bekker soil does not.
  EXPECT_NE(Error("schema_version: 1\n").find("zeta_N_cm3: missing"), std::string::npos);
}

}  // namespace
}  // namespace touchdown::io
