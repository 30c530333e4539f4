// The effect library's model-file syntax: effects written and read back, bad files refused with
// file, field and value.
#include "drop_tests/model/effects.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/model/effects_yaml.h"
#include "drop_tests/model/model_file.h"
#include "rft/input_error.h"

namespace touchdown::model {
namespace {

TEST(EffectFile, ParsesWritesAndRejects) {
  const std::vector<Effect> effects{{"gas_cushion", {0.3, 5000.0}}, {"compaction_peak", {2e4, 0.003}}};
  const YAML::Node node = EffectsToYaml(effects, {{{0.25, 0.35}, {4000.0, 6000.0}}, {}});
  EXPECT_DOUBLE_EQ(node["compaction_peak"]["d_c_mm"].as<double>(), 3.0);
  const std::vector<Effect> back = ParseEffects(io::YamlFields(node, "m.yaml", "effects"));
  ASSERT_EQ(back.size(), 2u);
  for (const Effect& e : back) {
    const auto& orig = e.id == "gas_cushion" ? effects[0] : effects[1];
    for (size_t i = 0; i < e.values.size(); ++i) EXPECT_NEAR(e.values[i], orig.values[i], 1e-12 * std::abs(orig.values[i]));
  }
  auto rejects = [](const std::string& yaml, const std::string& needle) {
    try {
      ParseEffects(io::YamlFields(YAML::Load(yaml), "m.yaml", "effects"));
      ADD_FAILURE() << "accepted " << yaml;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  rejects("{ballistic: {k: 1}}", "effects.ballistic");
  rejects("{gas_cushion: {chi: 1.5, c_g_N_s_m3: 1}}", "effects.gas_cushion.chi");
  rejects("{gas_cushion: {chi: 0.2}}", "effects.gas_cushion.c_g_N_s_m3");
  rejects("{rate_damping: {c_N_s_m3: 10, c_g: 1}}", "c_g");
  // The model file hook: a valid effect loads, a bad one is named.
  const std::string dir = ::testing::TempDir() + "/effects_model";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/good.yaml") << "schema_version: 1\ntype: model\neffects:\n  rate_damping: {c_N_s_m3: 100}\n";
  std::ofstream(dir + "/bad.yaml") << "schema_version: 1\ntype: model\neffects:\n  rate_damping: {c_N_s_m3: -1}\n";
  const ModelFile m = LoadModelFile(dir + "/good.yaml");
  EXPECT_TRUE(m.HasEffects());
  EXPECT_THROW(LoadModelFile(dir + "/bad.yaml"), InputError);
}

// The library is one table in EffectId's order, the eight built-in effects and then the registered
// ones (rft/effects/): each id's entry is found by its kind and by its name, and the terms each
// effect sets are read back as that effect (and only it) active.
TEST(EffectLibrary, OneTableInEnumOrder) {
  const std::vector<EffectInfo>& library = EffectLibrary();
  ASSERT_EQ(library.size(), static_cast<size_t>(EffectId::kRegisteredBegin) + rft::RegisteredEffects().size());
  for (size_t i = 0; i < rft::RegisteredEffects().size(); ++i)
    EXPECT_EQ(library[static_cast<size_t>(EffectId::kRegisteredBegin) + i].registered, &rft::RegisteredEffects()[i]);
  for (size_t i = 0; i < library.size(); ++i) {
    const EffectId kind = static_cast<EffectId>(i);
    EXPECT_EQ(library[i].kind, kind);
    EXPECT_EQ(&FindEffect(kind), &library[i]);
    EXPECT_EQ(&FindEffect(library[i].id), &library[i]);
    std::vector<double> values;
    for (const EffectParameterInfo& p : library[i].parameters) values.push_back(0.25 * p.lower + 0.75 * p.upper);
    const rft::EffectTerms t = MakeEffectTerms({{library[i].id, values}});
    EXPECT_EQ(ActiveEffectIds(t), std::vector<EffectId>{kind}) << library[i].id;
    EXPECT_EQ(ActiveEffects(t), std::vector<std::string>{library[i].id});
  }
  EXPECT_EQ(FindEffect(EffectId::kRateDamping).id, "rate_damping");
  EXPECT_TRUE(FindEffect(EffectId::kGasCushion).air_only);
  EXPECT_TRUE(FindEffect(EffectId::kSensorOffset).measurement_only);
  EXPECT_TRUE(FindEffect(EffectId::kInertialDrag).needs_bulk_density);
  EXPECT_TRUE(FindEffect(EffectId::kAddedMass).needs_bulk_density);
  EXPECT_TRUE(FindEffect(EffectId::kAddedMassPlug).needs_bulk_density);
}

// A value in a file is in its key's unit: a parameter scaled from SI for its file names that unit,
// and its key ends in it (diagnosis.json reports each estimate in it).
TEST(EffectLibrary, EveryScaledParameterNamesItsFileUnitAsItsKeyEnds) {
  for (const EffectInfo& e : EffectLibrary())
    for (const EffectParameterInfo& p : e.parameters) {
      if (p.file_to_si == 1.0) {
        EXPECT_EQ(p.FileUnit(), p.unit) << e.id << "." << p.key;
        continue;
      }
      ASSERT_FALSE(p.file_unit.empty()) << e.id << "." << p.key;
      const std::string suffix = "_" + p.file_unit;
      EXPECT_TRUE(p.key.size() > suffix.size() && p.key.ends_with(suffix)) << e.id << "." << p.key;
    }
  EXPECT_EQ(FindEffect(EffectId::kCompactionPeak).parameters[1].FileUnit(), "mm");
  EXPECT_EQ(FindEffect(EffectId::kRateDamping).parameters[0].FileUnit(), "N s/m^3");
}

TEST(EffectLibrary, EffectsNotAppliedFollowTheTable) {
  const rft::EffectTerms t = MakeEffectTerms({{"gas_cushion", {0.3, 1e3}}, {"sensor_offset", {1e-3, 0.0}},
                                              {"rate_damping", {1e3}}});
  const auto in_vacuum = EffectsNotApplied(t, false);
  ASSERT_EQ(in_vacuum.size(), 2u);
  EXPECT_EQ(in_vacuum[0].first, "gas_cushion");
  EXPECT_EQ(in_vacuum[1].first, "sensor_offset");
  const auto in_air = EffectsNotApplied(t, true);
  ASSERT_EQ(in_air.size(), 1u);
  EXPECT_EQ(in_air[0].first, "sensor_offset");
}

}  // namespace
}  // namespace touchdown::model
