// Model files: written and read back, applied to soils with the gravity scaling, and refused
// (with the file and field named) when malformed or carrying unknown or out-of-range effects.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/model_file.h"
#include "rft/input_error.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::model;
using namespace touchdown::io;

fs::path TempFile(const std::string& name) {
  return fs::temp_directory_path() / ("touchdown_model_" + std::to_string(::getpid()) + "_" + name);
}

TEST(ModelFile, WriteThenLoadKeepsOverridesIntervalsAndFit) {
  ModelFile m;
  m.name = "lab";
  SoilOverride o;
  o.zeta_N_m3 = 4.25e6;
  o.reference_gravity_m_s2 = 1.62;
  o.zeta_low_N_m3 = 4.0e6;
  o.zeta_high_N_m3 = 4.5e6;
  o.confidence = 0.9;
  o.fit = SoilFit{"least squares", 6, 240, 3.5, "/data/lab"};
  m.soils["fjs1_lp"] = o;
  const fs::path path = TempFile("roundtrip.yaml");
  WriteModelFile(m, path.string());
  const ModelFile back = LoadModelFile(path.string());
  fs::remove(path);
  ASSERT_EQ(back.soils.count("fjs1_lp"), 1u);
  const SoilOverride& b = back.soils.at("fjs1_lp");
  EXPECT_NEAR(b.zeta_N_m3, 4.25e6, 1e-3);
  EXPECT_DOUBLE_EQ(b.reference_gravity_m_s2, 1.62);
  EXPECT_NEAR(*b.zeta_low_N_m3, 4.0e6, 1e-3);
  EXPECT_NEAR(*b.zeta_high_N_m3, 4.5e6, 1e-3);
  EXPECT_DOUBLE_EQ(b.confidence, 0.9);
  ASSERT_TRUE(b.fit.has_value());
  EXPECT_EQ(b.fit->drops, 6);
  EXPECT_EQ(b.fit->samples, 240);
  EXPECT_FALSE(back.HasEffects());
}

TEST(ModelFile, ApplyConvertsToTheSoilsReferenceGravity) {
  ModelFile m;
  SoilOverride o;
  o.zeta_N_m3 = 1.0e6;             // 1 N/cm^3 at lunar gravity ...
  o.reference_gravity_m_s2 = 1.62;
  m.soils["fjs1_lp"] = o;
  const touchdown::rft::SoilParameters soil = LoadSoil("fjs1_lp");  // ... soil referenced to 9.81
  const touchdown::rft::SoilParameters applied = ApplyModel(m, soil);
  EXPECT_NEAR(applied.ZetaAtGravity(1.62), 1.0e6, 1e-6);
  EXPECT_NEAR(applied.ZetaAtGravity(9.81), 1.0e6 * 9.81 / 1.62, 1e-3);
  const touchdown::rft::SoilParameters other = ApplyModel(m, LoadSoil("fjs1_cp"));  // no override
  EXPECT_EQ(other.zeta_N_m3, LoadSoil("fjs1_cp").zeta_N_m3);
  // A calibrated lambda replaces the soil file's; the soil's own zeta at its own reference gravity
  // (what a lambda-only calibration carries) is kept without a round trip through g.
  SoilOverride l;
  l.zeta_N_m3 = soil.zeta_N_m3;
  l.reference_gravity_m_s2 = soil.reference_gravity_m_s2;
  l.dynamic_lambda = 0.7;
  m.soils["fjs1_lp"] = l;
  EXPECT_EQ(ApplyModel(m, soil).dynamic_lambda, 0.7);
  EXPECT_EQ(ApplyModel(m, soil).zeta_N_m3, soil.zeta_N_m3);
}

TEST(ModelFile, BekkerFieldsReplaceTheSoilFilesAndNoZetaKeepsItsZeta) {
  const touchdown::rft::SoilParameters soil = LoadSoil("lunar_nominal_bekker");
  ModelFile m;
  SoilOverride o;  // no zeta: a Bekker soil's override
  o.bekker_n = 1.2;
  o.bekker_k_phi_N_m_n2 = 1.0e6;
  m.soils["lunar_nominal_bekker"] = o;
  const touchdown::rft::SoilParameters applied = ApplyModel(m, soil);
  EXPECT_EQ(applied.bekker.n, 1.2);
  EXPECT_EQ(applied.bekker.k_phi_N_m_n2, 1.0e6);
  EXPECT_EQ(applied.bekker.k_c_N_m_n1, soil.bekker.k_c_N_m_n1);  // not given: the file's
  EXPECT_EQ(applied.bekker.cohesion_Pa, soil.bekker.cohesion_Pa);
  EXPECT_EQ(applied.zeta_N_m3, soil.zeta_N_m3);
  EXPECT_EQ(applied.reference_gravity_m_s2, soil.reference_gravity_m_s2);
}

// A calibration that frees only lambda writes no zeta, so the soil file's is kept to the last bit
// (a zeta written in decimal and read back would not be).
TEST(ModelFile, ALambdaOnlyOverrideWritesNoZetaAndKeepsTheSoilsExactly) {
  const touchdown::rft::SoilParameters soil = LoadSoil("fjs1_lp");
  ModelFile m;
  SoilOverride o;
  o.dynamic_lambda = 0.7;
  m.soils["fjs1_lp"] = o;
  const fs::path path = TempFile("lambda_only.yaml");
  WriteModelFile(m, path.string());
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const ModelFile back = LoadModelFile(path.string());
  fs::remove(path);
  EXPECT_EQ(text.find("zeta"), std::string::npos) << text;
  EXPECT_EQ(back.soils.at("fjs1_lp").zeta_N_m3, 0.0);
  const touchdown::rft::SoilParameters applied = ApplyModel(back, soil);
  EXPECT_EQ(applied.dynamic_lambda, 0.7);
  EXPECT_EQ(applied.zeta_N_m3, soil.zeta_N_m3);
  EXPECT_EQ(applied.reference_gravity_m_s2, soil.reference_gravity_m_s2);
}

struct BadModel {
  const char* name;
  std::string text;
  std::string expected;
};
void PrintTo(const BadModel& c, std::ostream* os) { *os << c.name; }  // readable test names

class ModelFileBad : public ::testing::TestWithParam<BadModel> {};

TEST_P(ModelFileBad, RefusedNamingTheField) {
  const fs::path path = TempFile(std::string(GetParam().name) + ".yaml");
  std::ofstream(path) << GetParam().text;
  try {
    const ModelFile m = LoadModelFile(path.string());
    ApplyModel(m, LoadSoil("fjs1_lp"));
    fs::remove(path);
    FAIL() << "accepted";
  } catch (const touchdown::InputError& e) {
    fs::remove(path);
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ModelFileBad,
    ::testing::Values(
        BadModel{"WrongType", "type: sweep\n", "type: must be 'model'"},
        BadModel{"NegativeZeta", "type: model\nsoils: {fjs1_lp: {zeta_N_cm3: -1}}\n", "soils.fjs1_lp.zeta_N_cm3"},
        BadModel{"ReversedInterval", "type: model\nsoils: {fjs1_lp: {zeta_N_cm3: 3, zeta_interval_N_cm3: [4, 2]}}\n",
                 "zeta_interval_N_cm3"},
        BadModel{"UnknownField", "type: model\nsoil: {}\n", "soil: unknown field"},
        BadModel{"NegativeLambda", "type: model\nsoils: {fjs1_lp: {zeta_N_cm3: 3, dynamic_lambda: -0.5}}\n",
                 "soils.fjs1_lp.dynamic_lambda"},
        BadModel{"BekkerNAboveFive", "type: model\nsoils: {fjs1_lp: {bekker: {n: 6}}}\n", "soils.fjs1_lp.bekker.n"},
        BadModel{"BekkerNegativeKphi", "type: model\nsoils: {fjs1_lp: {bekker: {k_phi_kN_m_n2: -1}}}\n",
                 "soils.fjs1_lp.bekker.k_phi_kN_m_n2"},
        BadModel{"BekkerUnknownKey", "type: model\nsoils: {fjs1_lp: {bekker: {cohesion_kPa: 1}}}\n",
                 "soils.fjs1_lp.bekker.cohesion_kPa"},
        BadModel{"BekkerEmpty", "type: model\nsoils: {fjs1_lp: {bekker: {}}}\n", "soils.fjs1_lp.bekker"},
        BadModel{"GravityWithoutZeta", "type: model\nsoils: {fjs1_lp: {bekker: {n: 1}, reference_gravity_m_s2: 1.62}}\n",
                 "soils.fjs1_lp.reference_gravity_m_s2"},
        BadModel{"NothingGiven", "type: model\nsoils: {fjs1_lp: {}}\n", "soils.fjs1_lp.zeta_N_cm3: is required"},
        BadModel{"GravityWithLambdaOnly", "type: model\nsoils: {fjs1_lp: {dynamic_lambda: 1, reference_gravity_m_s2: 1.62}}\n",
                 "soils.fjs1_lp.reference_gravity_m_s2"},
        BadModel{"UnknownEffect", "type: model\neffects: {air_drag: {k: 1}}\n", "effects.air_drag: unknown effect"},
        BadModel{"EffectOutOfRange", "type: model\neffects: {gas_cushion: {chi: 1.5, c_g_N_s_m3: 0}}\n",
                 "effects.gas_cushion.chi: must be in [0, 0.95]"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
