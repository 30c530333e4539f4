#pragma once
// What the reference of an input file says about each key of each block (docs/reference.md,
// `touchdown schema`), generated from the tables its loader reads with (key_table.h,
// field_table.h), so that the reference cannot drift from the code: the keys in the order they are
// written, each key's unit (from its suffix), and for the keys read from a number table the
// range the loader accepts and the default it takes when the key is absent. What a key means is
// the reference's own text.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace touchdown::io {

struct KeyDoc {
  std::string key;
  std::string unit;           // from the key's suffix ("mm", "N/cm^3"); "-" when it has none
  std::string range;          // a number's accepted values ("(0, 1e+04]", "> 0"); "" when not generated
  std::string default_value;  // a number's ("*required*", "9.81"); "" when not generated
};

struct BlockDoc {
  std::string id;        // the file type, then the block's path: "pad.profile", "lander_scenario.ground"
  std::string read_by;   // the source file whose loader reads the block
  std::vector<KeyDoc> keys;
};

// A block's reference: its keys in order; a key without a unit suffix in a block whose own key has
// one (`inertia_kg_m2: {ixx: ...}`) takes the block's unit.
BlockDoc MakeBlock(std::string id, std::string read_by, std::vector<KeyDoc> keys);

// The unit a key's suffix names ("radius_mm" -> "mm", "zeta_N_cm3" -> "N/cm^3"); "-" without one.
std::string UnitOfKey(std::string_view key);

// A key with no number table behind it: its unit from the suffix, nothing else generated.
KeyDoc PlainKeyDoc(std::string_view key);
std::vector<KeyDoc> PlainKeyDocs(const std::vector<std::string>& keys);

// `touchdown schema`'s outputs: one markdown table per block, or every block as JSON.
std::string SchemaMarkdown(const std::vector<BlockDoc>& blocks);
nlohmann::json SchemaJson(const std::vector<BlockDoc>& blocks);

}  // namespace touchdown::io
