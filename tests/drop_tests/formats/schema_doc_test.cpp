// What the reference says about a key comes from the tables the loaders read with
// (drop_tests/formats/schema_doc.h): units from suffixes, ranges and defaults from number fields.
#include "drop_tests/formats/schema_doc.h"

#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::io {
namespace {

TEST(UnitOfKey, TheLongestSuffixThatEndsTheKeyNamesItsUnit) {
  EXPECT_EQ(UnitOfKey("radius_mm"), "mm");
  EXPECT_EQ(UnitOfKey("zeta_N_cm3"), "N/cm^3");
  EXPECT_EQ(UnitOfKey("gravity_m_s2"), "m/s^2");
  EXPECT_EQ(UnitOfKey("impact_speed_m_s"), "m/s");
  EXPECT_EQ(UnitOfKey("max_step_s"), "s");
  EXPECT_EQ(UnitOfKey("penetration_drift_mm_s"), "mm/s");
  EXPECT_EQ(UnitOfKey("damping_N_m_s_rad"), "N m s/rad");
  EXPECT_EQ(UnitOfKey("c_N_s_m3"), "N s/m^3");
  EXPECT_EQ(UnitOfKey("dt_ms"), "ms");
  EXPECT_EQ(UnitOfKey("k_c_kN_m_n1"), "kN/m^(n+1)");
  EXPECT_EQ(UnitOfKey("sample_rate_hz"), "Hz");
  // A key that is only a suffix, or has none, has no unit.
  EXPECT_EQ(UnitOfKey("mm"), "-");
  EXPECT_EQ(UnitOfKey("segments"), "-");
  EXPECT_EQ(UnitOfKey("mu_surf"), "-");
}

struct Block {
  double length_m = 0.25;
  double angle_rad = 0.0;
  double count = 3.0;
  double derived = 0.0;
};
const limits::Range kLength{"mm", 0.0, 5000.0, true};

TEST(DocOf, ANumberFieldGivesItsRangeInFileUnitsAndItsDefaultOrRequired) {
  const FieldTable<Block> fields{
      {"length_mm", &Block::length_m, units::kMm, Sign::kPositive, true, false, &kLength},
      {"angle_deg", &Block::angle_rad, units::kDeg, Sign::kNonNegative, false},
      {"count", &Block::count, 1.0, Sign::kAny},
      {"derived_mm", &Block::derived, units::kMm, Sign::kPositive, true, false, nullptr, "`length_mm`"},
  };
  const std::vector<KeyDoc> docs = DocsOf(fields);
  ASSERT_EQ(docs.size(), 4u);
  EXPECT_EQ(docs[0].key, "length_mm");
  EXPECT_EQ(docs[0].unit, "mm");
  EXPECT_EQ(docs[0].range, "(0, 5000]");
  EXPECT_EQ(docs[0].default_value, "250");  // the member's 0.25 m, in the file's mm
  EXPECT_EQ(docs[1].range, ">= 0");
  EXPECT_EQ(docs[1].default_value, "*required*");
  EXPECT_EQ(docs[2].range, "any");
  EXPECT_EQ(docs[2].default_value, "3");
  EXPECT_EQ(docs[3].default_value, "`length_mm`");  // a default the loader derives says so
}

TEST(DocsOf, AKeyTableGivesItsNumberFieldsDocsAndOnlyTheUnitOfItsOtherKeys) {
  const FieldTable<Block> fields{{"length_mm", &Block::length_m, units::kMm, Sign::kPositive, false, false, &kLength}};
  KeyTable<Block> keys{{"name"}, {"width_mm"}};
  AppendNumberKeys(keys, fields);
  const std::vector<KeyDoc> docs = DocsOf(keys, {"name"});
  ASSERT_EQ(docs.size(), 2u);
  EXPECT_EQ(docs[0].key, "width_mm");
  EXPECT_EQ(docs[0].unit, "mm");
  EXPECT_EQ(docs[0].range, "");  // not generated: the reference's own text
  EXPECT_EQ(docs[0].default_value, "");
  EXPECT_EQ(docs[1].key, "length_mm");
  EXPECT_EQ(docs[1].range, "(0, 5000]");
  EXPECT_EQ(docs[1].default_value, "*required*");
}

TEST(RangeText, APositiveSignOpensTheLowEndOnlyWhereTheRangeStartsAtZeroOrBelow) {
  const limits::Range from_zero{"kg", 0.0, 10.0, false}, from_tiny{"kg", 1e-6, 10.0, false};
  EXPECT_EQ(RangeText(Sign::kPositive, &from_zero), "(0, 10]");
  EXPECT_EQ(RangeText(Sign::kPositive, &from_tiny), "[1e-06, 10]");  // 1e-6 itself is accepted
  EXPECT_EQ(RangeText(Sign::kNonNegative, &from_zero), "[0, 10]");
  EXPECT_EQ(RangeText(Sign::kNonNegative, nullptr), ">= 0");
}

TEST(NumberKey, ItsDocSaysItsRangeAndDefaultAndDocsWithReplacesOnlyItsKey) {
  const NumberKey gravity{"gravity_m_s2", Sign::kPositive, nullptr, nullptr, 9.81};
  const NumberKey speed{"speed_m_s", Sign::kPositive};
  const NumberKey mass{"mass_kg", Sign::kPositive, &kLength, "the pad's"};
  EXPECT_EQ(DocOf(gravity).default_value, "9.81");
  EXPECT_EQ(DocOf(speed).default_value, "*required*");
  EXPECT_EQ(DocOf(mass).default_value, "the pad's");
  const std::vector<KeyDoc> docs = DocsWith({"pad", "speed_m_s", "gravity_m_s2"}, {gravity, speed});
  ASSERT_EQ(docs.size(), 3u);
  EXPECT_EQ(docs[0].range, "");
  EXPECT_EQ(docs[1].range, "> 0");
  EXPECT_EQ(docs[2].unit, "m/s^2");
  EXPECT_EQ(docs[2].default_value, "9.81");
}

TEST(MakeBlock, KeysWithoutASuffixTakeTheUnitOfTheBlocksKey) {
  const BlockDoc block = MakeBlock("pad.inertia_kg_m2", "here.cpp", PlainKeyDocs({"ixx", "offset_mm"}));
  EXPECT_EQ(block.keys[0].unit, "kg m^2");
  EXPECT_EQ(block.keys[1].unit, "mm");
  EXPECT_EQ(MakeBlock("pad", "here.cpp", PlainKeyDocs({"name"})).keys[0].unit, "-");
}

TEST(SchemaJson, ListsEachBlockWithItsKeysInOrder) {
  const nlohmann::json json = SchemaJson({MakeBlock("soil.bekker", "soil_file.cpp", PlainKeyDocs({"n", "cohesion_kPa"}))});
  ASSERT_EQ(json.size(), 1u);
  EXPECT_EQ(json[0]["id"], "soil.bekker");
  EXPECT_EQ(json[0]["read_by"], "soil_file.cpp");
  EXPECT_EQ(json[0]["keys"][1]["key"], "cohesion_kPa");
  EXPECT_EQ(json[0]["keys"][1]["unit"], "kPa");
}

TEST(SchemaMarkdown, EscapesABarInACellAndMarksAnEmptyCell) {
  BlockDoc block = MakeBlock("sweep.simulation", "x.cpp", PlainKeyDocs({"free_drop_model"}));
  block.keys[0].default_value = "reference | fast";
  const std::string md = SchemaMarkdown({block});
  EXPECT_NE(md.find("| `free_drop_model` | - | - | reference \\| fast |"), std::string::npos) << md;
}

}  // namespace
}  // namespace touchdown::io
