#pragma once
// One block's keys in the order its writer writes them (a file type's top level, or one of its
// blocks). The loader accepts exactly these keys (YamlFields::RequireOnly(Keys(table))) and the
// writer walks the same table (WriteMap), so a key written is always a key read back, and a key
// added in one place is added for both. Each key says when a value has it and how its value is
// written; a key with no writer is one only a person writes (description, provenance). What the
// loader makes of a value, with the checks that tie several keys together, stays with the loader.
// Number fields come from their FieldTable (field_table.h), written as WriteFields writes them.
//
// Private to the .cpp files of the YAML edge (it writes YAML).
#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "drop_tests/formats/field_table.h"

namespace touchdown::io {

template <typename T>
struct FileKey {
  const char* key;
  std::function<bool(const T&)> written{};                 // empty: never written (a person's text)
  std::function<void(YAML::Emitter&, const T&)> value{};   // writes the value (the key is written before)
  std::optional<KeyDoc> doc{};  // the reference's unit, range and default of a number field; none: the unit only
};

template <typename T>
using KeyTable = std::vector<FileKey<T>>;

// For FileKey::written: a key every value has.
template <typename T>
bool Always(const T&) {
  return true;
}

// The number fields of `fields` as keys of a table over `V`, whose `part` holds them (written as
// WriteFields writes them: in file units, leaving out the defaults of the fields that say so), and
// only when `when` holds if there is one (fields written together or not at all).
template <typename V, typename T>
void AppendNumberKeys(KeyTable<V>& table, const FieldTable<T>& fields, std::function<const T&(const V&)> part,
                      std::function<bool(const V&)> when = {}) {
  for (const NumberField<T>& field : fields) {
    table.push_back({field.key,
                     [field, part, when](const V& v) {
                       if (when && !when(v)) return false;
                       return !(field.omit_default && part(v).*field.member == T{}.*field.member);
                     },
                     [field, part](YAML::Emitter& y, const V& v) { y << part(v).*field.member / field.file_to_si; },
                     DocOf(field)});
  }
}
template <typename T>
void AppendNumberKeys(KeyTable<T>& table, const FieldTable<T>& fields) {
  AppendNumberKeys<T, T>(table, fields, [](const T& v) -> const T& { return v; });
}

// The table's keys, for YamlFields::RequireOnly, less those in `except` (keys a variant of the
// file type does not have).
template <typename T>
std::vector<std::string> Keys(const KeyTable<T>& table, std::initializer_list<std::string_view> except = {}) {
  std::vector<std::string> keys;
  for (const FileKey<T>& k : table)
    if (std::find(except.begin(), except.end(), std::string_view(k.key)) == except.end()) keys.push_back(k.key);
  return keys;
}

// What the reference says about the table's keys (schema_doc.h), less those in `except`.
template <typename T>
std::vector<KeyDoc> DocsOf(const KeyTable<T>& table, std::initializer_list<std::string_view> except = {}) {
  std::vector<KeyDoc> docs;
  for (const FileKey<T>& k : table)
    if (std::find(except.begin(), except.end(), std::string_view(k.key)) == except.end())
      docs.push_back(k.doc ? *k.doc : PlainKeyDoc(k.key));
  return docs;
}

// Writes `value` as a map of every key it has, in table order; YAML::Flow for a one-line map.
template <typename T>
void WriteMap(YAML::Emitter& y, const KeyTable<T>& table, const T& value, std::optional<YAML::EMITTER_MANIP> style = {}) {
  if (style) y << *style;
  y << YAML::BeginMap;
  for (const FileKey<T>& k : table) {
    if (!k.written || !k.written(value)) continue;
    y << YAML::Key << k.key << YAML::Value;
    k.value(y, value);
  }
  y << YAML::EndMap;
}

// A FileKey's writer for a block that is a map of its own table (`table` returns that table).
template <typename T>
std::function<void(YAML::Emitter&, const T&)> MapOf(const KeyTable<T>& (*table)()) {
  return [table](YAML::Emitter& y, const T& value) { WriteMap(y, table(), value); };
}

}  // namespace touchdown::io
