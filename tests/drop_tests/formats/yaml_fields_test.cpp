// The one YAML loader: what yaml-cpp would accept but a touchdown file must not hold is refused at
// load, with the file and the reason, before any loader walks the tree.
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::io {
namespace {

class YamlLoad : public testing_scratch::ScratchDirTest {
 protected:
  // The message of the InputError that loading `text` raises ("" when it loads).
  std::string Refusal(const std::string& text) {
    const std::string path = Write("f.yaml", text);
    try {
      YamlFields::LoadFile(path);
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find(path), std::string::npos) << message;
      return message;
    }
    return "";
  }
};

// An alias inside its own anchor makes an infinitely deep tree: a walk over it never ended (a
// stack overflow, exit 139).
TEST_F(YamlLoad, AliasInsideItsOwnAnchorIsRefused) {
  EXPECT_NE(Refusal("a: &a [*a]\n").find("nested more than 64 levels"), std::string::npos);
  EXPECT_NE(Refusal("mass_kg: 1\nb: &b {c: *b}\n").find("nested more than 64 levels"), std::string::npos);
}

// Aliases of aliases multiply: 9 levels of 10 references stand for 10^9 values. The walk stops
// at the node bound, in well under a second, instead of running for minutes.
TEST_F(YamlLoad, AliasExpansionIsBounded) {
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string prev = "*l" + std::to_string(level - 1);
    text += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [" + prev;
    for (int i = 1; i < 10; ++i) text += ", " + prev;
    text += "]\n";
  }
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(Refusal(text).find("expands to more than 1000000 values"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// Aliases within the bounds are ordinary YAML and load.
TEST_F(YamlLoad, ModestAliasesLoad) {
  EXPECT_EQ(Refusal("a: &a {x: 1}\nb: *a\nc: [*a, *a]\n"), "");
}

TEST_F(YamlLoad, ASecondDocumentIsRefused) {
  EXPECT_NE(Refusal("mass_kg: 1\n---\nmass_kg: 2\n").find("holds a second YAML document (line 2)"),
            std::string::npos);
  EXPECT_NE(Refusal("mass_kg: 1\n...\nmass_kg: 2\n").find("holds a second YAML document (line 3)"),
            std::string::npos);
  // A document end marker with nothing after it is one document.
  EXPECT_EQ(Refusal("mass_kg: 1\n...\n"), "");
  EXPECT_EQ(Refusal("---\nmass_kg: 1\n"), "");
}

// Malformed text on which yaml-cpp's LoadAll never returned (found by the soil and model YAML
// fuzzers): refused at once.
TEST_F(YamlLoad, MalformedTextIsRefusedAtOnce) {
  EXPECT_NE(Refusal(", The lunar soar soiekker-Wongeters), vacuum.\natmosphere: vacuum\nlaw: bekker\nbekker:\n"
                    "  n: 2\n  k_c_re do not depend on it.\n"),
            "");
  EXPECT_NE(Refusal(",ype: \nsoils: Dfjs2_lp:3{z 2],onz i"), "");
}

// A block of numbers only: its known keys are its number fields, in table order.
TEST(FieldTableKeys, TheTablesKeysInOrder) {
  struct Block {
    double a = 0.0, b = 0.0;
  };
  const FieldTable<Block> fields{{"a_m", &Block::a}, {"b_deg", &Block::b}};
  EXPECT_EQ(FieldKeys(fields), (std::vector<std::string>{"a_m", "b_deg"}));
}

// A key table is both lists: the loader's known keys (less a variant's) and the writer's order. A
// key is written only when the value has it, a person's key (no writer) never, and the number
// fields as WriteFields writes them (file units, a default left out where the field says so).
struct Pad {
  std::string name;
  double radius_m = 0.0, segments = 0.0;
  bool dynamic = false;
};
const KeyTable<Pad>& PadKeys() {
  using Y = YAML::Emitter;
  static const KeyTable<Pad> keys = [] {
    KeyTable<Pad> k{{"name", Always<Pad>, [](Y& y, const Pad& p) { y << p.name; }}, {"description"}};
    AppendNumberKeys(k, FieldTable<Pad>{{"radius_mm", &Pad::radius_m, 1e-3},
                                        {"segments", &Pad::segments, 1.0, Sign::kPositive, true, true}});
    k.push_back({"dynamic", [](const Pad& p) { return p.dynamic; }, [](Y& y, const Pad&) { y << true; }});
    return k;
  }();
  return keys;
}
std::string Written(const Pad& pad) {
  YAML::Emitter y;
  WriteMap(y, PadKeys(), pad, YAML::Flow);
  return y.c_str();
}

TEST(KeyTable, IsTheLoadersKeysAndTheWritersOrder) {
  EXPECT_EQ(Keys(PadKeys()), (std::vector<std::string>{"name", "description", "radius_mm", "segments", "dynamic"}));
  EXPECT_EQ(Keys(PadKeys(), {"description", "dynamic"}), (std::vector<std::string>{"name", "radius_mm", "segments"}));
  EXPECT_EQ(Written({"flat", 0.05, 0.0, false}), "{name: flat, radius_mm: 50}");
  EXPECT_EQ(Written({"flat", 0.05, 16.0, true}), "{name: flat, radius_mm: 50, segments: 16, dynamic: true}");
}

// What the writer writes, the loader's key list accepts: YamlFields::RequireOnly passes it.
TEST(KeyTable, WhatItWritesItsLoaderAccepts) {
  const YamlFields f(YAML::Load(Written({"flat", 0.05, 16.0, true})), "pad.yaml", "");
  EXPECT_NO_THROW(f.RequireOnly(Keys(PadKeys())));
  EXPECT_THROW(f.RequireOnly(Keys(PadKeys(), {"dynamic"})), InputError);
}

// A name read from a file becomes part of file names: one that could leave the output folder is
// refused where it is read, naming the file and the field; the file's stem stands in when the key
// is left out, and is checked the same way.
TEST(YamlName, ANameThatCouldLeaveTheOutputFolderIsRefusedAtLoad) {
  const YamlFields good(YAML::Load("name: flat\n"), "pad.yaml", "");
  EXPECT_EQ(good.Name("name", "stem"), "flat");
  EXPECT_EQ(YamlFields(YAML::Load("mass_kg: 1\n"), "pad.yaml", "").Name("name", "stem"), "stem");
  const auto refusal = [](const std::string& text, const std::string& fallback) {
    try {
      YamlFields(YAML::Load(text), "pad.yaml", "patch").Name("name", fallback);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal("name: ../../../PWNED\n", "x"), "pad.yaml: patch.name: '../../../PWNED' contains '/' (it names files)");
  EXPECT_EQ(refusal("name: /some/dir/ABS\n", "x"), "pad.yaml: patch.name: '/some/dir/ABS' contains '/' (it names files)");
  EXPECT_EQ(refusal("name: \"a\\tb\"\n", "x"), "pad.yaml: patch.name: contains a control character (it names files)");
  EXPECT_EQ(refusal("name: ..\n", "x"), "pad.yaml: patch.name: '..' cannot be a file name");
  EXPECT_EQ(refusal("mass_kg: 1\n", ".."),
            "pad.yaml: patch.name: '..' cannot be a file name, and the file's name gives it where the key is left out");
}

}  // namespace
}  // namespace touchdown::io
