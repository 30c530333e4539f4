// Model files: loaded, written with WriteModelFile and loaded again give the same model (soil
// overrides with intervals and fit records, effects with their 95 % intervals, provenance), and
// writing that model again gives the same text.
#include <gtest/gtest.h>

#include <fstream>

#include "drop_tests/model/model_file.h"
#include "tests/round_trip.h"

namespace touchdown::model {
namespace {

struct ModelRoundTrip : testing_scratch::ScratchDirTest {};

void ExpectSameModel(const ModelFile& a, const ModelFile& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  ASSERT_EQ(a.soils.size(), b.soils.size());
  for (const auto& [name, o] : a.soils) {
    SCOPED_TRACE(name);
    ASSERT_EQ(b.soils.count(name), 1u);
    const SoilOverride& p = b.soils.at(name);
    EXPECT_DOUBLE_EQ(o.zeta_N_m3, p.zeta_N_m3);
    EXPECT_EQ(o.reference_gravity_m_s2, p.reference_gravity_m_s2);
    ASSERT_EQ(o.zeta_low_N_m3.has_value(), p.zeta_low_N_m3.has_value());
    if (o.zeta_low_N_m3) {
      EXPECT_DOUBLE_EQ(*o.zeta_low_N_m3, *p.zeta_low_N_m3);
      EXPECT_DOUBLE_EQ(*o.zeta_high_N_m3, *p.zeta_high_N_m3);
      EXPECT_EQ(o.confidence, p.confidence);
    }
    EXPECT_EQ(o.dynamic_lambda, p.dynamic_lambda);
    for (const BekkerOverrideField& e : BekkerOverrideFields()) {
      ASSERT_EQ((o.*e.member).has_value(), (p.*e.member).has_value()) << e.key;
      if (o.*e.member) {
        EXPECT_DOUBLE_EQ(*(o.*e.member), *(p.*e.member)) << e.key;
      }
    }
    ASSERT_EQ(o.fit.has_value(), p.fit.has_value());
    if (o.fit) {
      EXPECT_EQ(o.fit->method, p.fit->method);
      EXPECT_EQ(o.fit->drops, p.fit->drops);
      EXPECT_EQ(o.fit->samples, p.fit->samples);
      EXPECT_EQ(o.fit->residual_rms_N, p.fit->residual_rms_N);
    }
  }
  ASSERT_EQ(a.effects.size(), b.effects.size());
  for (size_t k = 0; k < a.effects.size(); ++k) {
    EXPECT_EQ(a.effects[k].id, b.effects[k].id);
    ASSERT_EQ(a.effects[k].values.size(), b.effects[k].values.size());
    for (size_t i = 0; i < a.effects[k].values.size(); ++i)
      EXPECT_DOUBLE_EQ(a.effects[k].values[i], b.effects[k].values[i]);
  }
  ASSERT_EQ(a.effect_intervals.size(), b.effect_intervals.size());
  for (size_t k = 0; k < a.effect_intervals.size(); ++k) {
    ASSERT_EQ(a.effect_intervals[k].size(), b.effect_intervals[k].size());
    for (size_t i = 0; i < a.effect_intervals[k].size(); ++i) {
      EXPECT_DOUBLE_EQ(a.effect_intervals[k][i].first, b.effect_intervals[k][i].first);
      EXPECT_DOUBLE_EQ(a.effect_intervals[k][i].second, b.effect_intervals[k][i].second);
    }
  }
  EXPECT_EQ(a.provenance_yaml, b.provenance_yaml);
}

TEST_F(ModelRoundTrip, EveryPartOfAModelFile) {
  std::ofstream(Path("model.yaml"))
      << "schema_version: 1\ntype: model\nname: lab\ndescription: fitted on the lab drops\nsoils:\n"
         "  fjs1_lp:\n    zeta_N_cm3: 3.61\n    reference_gravity_m_s2: 1.62\n"
         "    zeta_interval_N_cm3: [3.52, 3.7]\n    confidence: 0.9\n"
         "    fit: {method: least squares, drops: 6, samples: 240, residual_rms_N: 4.1}\n"
         "  fjs1_cp:\n    zeta_N_cm3: 9.2\n    dynamic_lambda: 1.35\n"
         "effects:\n  gas_cushion:\n    chi: 0.3\n    c_g_N_s_m3: 3042.5\n"
         "    interval_95: {chi: [0.29, 0.31], c_g_N_s_m3: [2984, 3100]}\n"
         "  compaction_peak: {k_c_kg_m3: 20000, d_c_mm: 3}\n"
         "provenance:\n  diagnose: gas_cushion beats the base\n  runs: [1, 2]\n";
  const ModelFile first = LoadModelFile(Path("model.yaml"));
  ASSERT_EQ(first.effects.size(), 2u);
  EXPECT_EQ(first.effects[0].id, "gas_cushion");  // file order
  ASSERT_EQ(first.effect_intervals.size(), 2u);
  EXPECT_EQ(first.effect_intervals[0].size(), 2u);
  EXPECT_TRUE(first.effect_intervals[1].empty());
  EXPECT_DOUBLE_EQ(first.effects[1].values[1], 0.003);  // d_c in m
  EXPECT_EQ(first.soils.at("fjs1_cp").dynamic_lambda, 1.35);
  EXPECT_FALSE(first.soils.at("fjs1_lp").dynamic_lambda.has_value());

  testing_scratch::ExpectRoundTrip(
      first, Path("written_1.yaml"), Path("written_2.yaml"),
      [](const ModelFile& m, const std::string& path) { WriteModelFile(m, path); }, LoadModelFile, ExpectSameModel);
}

TEST_F(ModelRoundTrip, ABekkerSoilsOverrideWithoutZeta) {
  // A Bekker soil's calibrated n, k_c, k_phi (the soil file's keys and units); no zeta, none written.
  std::ofstream(Path("bekker.yaml"))
      << "schema_version: 1\ntype: model\nsoils:\n"
         "  lunar_nominal_bekker:\n    bekker: {n: 1.05, k_c_kN_m_n1: 2.5, k_phi_kN_m_n2: 900}\n"
         "  fjs1_cp_bekker:\n    bekker: {k_phi_kN_m_n2: 10100}\n";
  const ModelFile first = LoadModelFile(Path("bekker.yaml"));
  const SoilOverride& o = first.soils.at("lunar_nominal_bekker");
  EXPECT_EQ(o.zeta_N_m3, 0.0);
  EXPECT_EQ(*o.bekker_n, 1.05);
  EXPECT_EQ(*o.bekker_k_c_N_m_n1, 2.5e3);
  EXPECT_EQ(*o.bekker_k_phi_N_m_n2, 900e3);
  EXPECT_FALSE(first.soils.at("fjs1_cp_bekker").bekker_n.has_value());
  testing_scratch::ExpectRoundTrip(
      first, Path("bekker_1.yaml"), Path("bekker_2.yaml"),
      [](const ModelFile& m, const std::string& path) { WriteModelFile(m, path); }, LoadModelFile, ExpectSameModel);
  EXPECT_EQ(Slurp(Path("bekker_1.yaml")).find("zeta_N_cm3"), std::string::npos);
}

TEST_F(ModelRoundTrip, NoEffectsAndNoProvenance) {
  std::ofstream(Path("plain.yaml")) << "schema_version: 1\ntype: model\nsoils:\n  fjs1_lp: {zeta_N_cm3: 2.5}\n";
  const ModelFile first = LoadModelFile(Path("plain.yaml"));
  EXPECT_FALSE(first.HasEffects());
  EXPECT_TRUE(first.provenance_yaml.empty());
  WriteModelFile(first, Path("written.yaml"));
  ExpectSameModel(first, LoadModelFile(Path("written.yaml")));
  EXPECT_NE(Slurp(Path("written.yaml")).find("effects: {}"), std::string::npos);
}

}  // namespace
}  // namespace touchdown::model
