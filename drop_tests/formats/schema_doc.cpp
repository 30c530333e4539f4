#include "drop_tests/formats/schema_doc.h"

#include <array>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

namespace touchdown::io {

namespace {
// Key suffixes and the units they name, the longest of a family first ("_m_s2" before "_m_s"
// before "_s"), so the first that ends a key is its unit.
constexpr std::array<std::pair<std::string_view, std::string_view>, 32> kSuffixUnits{{
    {"_kN_m_n1", "kN/m^(n+1)"}, {"_kN_m_n2", "kN/m^(n+2)"}, {"_N_m_s_rad", "N m s/rad"},
    {"_N_m_rad", "N m/rad"},    {"_N_s_m3", "N s/m^3"},     {"_N_s_m", "N s/m"},
    {"_per_m2", "1/m^2"},
    {"_N_cm3", "N/cm^3"},       {"_N_cm2", "N/cm^2"},       {"_kg_m3", "kg/m^3"},
    {"_kg_m2", "kg m^2"},       {"_m_s2", "m/s^2"},         {"_deg_s", "deg/s"},
    {"_rad_s", "rad/s"},        {"_mm_s", "mm/s"},          {"_m_s", "m/s"},
    {"_N_s", "N/s"},            {"_N_m", "N/m"},            {"_per_mm", "1/mm"},
    {"_kPa", "kPa"},            {"_hz", "Hz"},              {"_Hz", "Hz"},
    {"_deg", "deg"},            {"_rad", "rad"},            {"_mm", "mm"},
    {"_ms", "ms"},              {"_kg", "kg"},              {"_J", "J"},
    {"_W", "W"},                {"_N", "N"},                {"_m", "m"},
    {"_s", "s"},
}};

bool EndsWith(std::string_view s, std::string_view tail) {
  return s.size() > tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// A markdown cell: "-" for nothing, and a `|` in text escaped so it does not split the row.
std::string Cell(const std::string& text) {
  if (text.empty()) return "-";
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}
}  // namespace

std::string UnitOfKey(std::string_view key) {
  for (const auto& [suffix, unit] : kSuffixUnits)
    if (EndsWith(key, suffix)) return std::string(unit);
  return "-";
}

BlockDoc MakeBlock(std::string id, std::string read_by, std::vector<KeyDoc> keys) {
  const std::string block_unit = UnitOfKey(id.substr(id.rfind('.') + 1));
  for (KeyDoc& k : keys)
    if (k.unit == "-") k.unit = block_unit;
  return {std::move(id), std::move(read_by), std::move(keys)};
}

KeyDoc PlainKeyDoc(std::string_view key) { return {std::string(key), UnitOfKey(key), "", ""}; }

std::vector<KeyDoc> PlainKeyDocs(const std::vector<std::string>& keys) {
  std::vector<KeyDoc> docs;
  for (const std::string& key : keys) docs.push_back(PlainKeyDoc(key));
  return docs;
}

std::string SchemaMarkdown(const std::vector<BlockDoc>& blocks) {
  std::ostringstream out;
  for (const BlockDoc& block : blocks) {
    out << "### " << block.id << "\n\nread by `" << block.read_by << "`\n\n| key | unit | range | default |\n|---|---|---|---|\n";
    for (const KeyDoc& k : block.keys)
      out << "| `" << k.key << "` | " << k.unit << " | " << Cell(k.range) << " | " << Cell(k.default_value) << " |\n";
    out << "\n";
  }
  return out.str();
}

nlohmann::json SchemaJson(const std::vector<BlockDoc>& blocks) {
  nlohmann::json out = nlohmann::json::array();
  for (const BlockDoc& block : blocks) {
    nlohmann::json keys = nlohmann::json::array();
    for (const KeyDoc& k : block.keys)
      keys.push_back({{"key", k.key}, {"unit", k.unit}, {"range", k.range}, {"default", k.default_value}});
    out.push_back({{"id", block.id}, {"read_by", block.read_by}, {"keys", std::move(keys)}});
  }
  return out;
}

}  // namespace touchdown::io
