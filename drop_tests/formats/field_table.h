#pragma once
// One description of a file type's number fields, walked by its loader and by its writer, so the
// two list the same keys with the same units and cannot drift apart. Each field names its key
// (unit-suffixed, as in the file), the member holding the SI value, the factor from file units,
// the sign it must have, whether it may be absent (then the member keeps its default) and
// whether the writer leaves out a value equal to that default (a 0 that means "unknown" and
// would not read back as a positive number), and the physical range it must lie in (file units,
// rft/physical_limits.h). Checks that tie several fields together stay with the loader that needs them.
//
// Private to the .cpp files of the YAML edge (it reads YamlFields and writes YAML).
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "drop_tests/formats/schema_doc.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/physical_limits.h"

namespace touchdown::io {

enum class Sign { kAny, kPositive, kNonNegative };

template <typename T>
struct NumberField {
  const char* key;           // in the file: "bulk_density_kg_m3", "internal_friction_angle_deg"
  double T::*member;         // SI
  double file_to_si = 1.0;   // value_SI = value_file * file_to_si
  Sign sign = Sign::kAny;
  bool optional = true;
  bool omit_default = false;
  const limits::Range* range = nullptr;  // in file units; none: any value of the sign
  const char* default_text = nullptr;    // the reference's default when the member's is not it (derived later)
};

template <typename T>
using FieldTable = std::vector<NumberField<T>>;

// The keys of a table, for YamlFields::RequireOnly (a block of numbers only; a block with other
// keys has a KeyTable, key_table.h).
template <typename T>
std::vector<std::string> FieldKeys(const FieldTable<T>& fields) {
  std::vector<std::string> keys;
  for (const NumberField<T>& field : fields) keys.push_back(field.key);
  return keys;
}

// The values a field accepts, as the reference states them: "(0, 1e+04]", "> 0", "any".
inline std::string RangeText(Sign sign, const limits::Range* range) {
  std::ostringstream out;
  if (range) {
    // A positive sign excludes the low end only where the range's own low end is 0 or below.
    const bool open = range->low_open || (sign == Sign::kPositive && range->low <= 0.0);
    out << (open ? "(" : "[") << range->low << ", " << range->high << "]";
    return out.str();
  }
  return sign == Sign::kPositive ? "> 0" : sign == Sign::kNonNegative ? ">= 0" : "any";
}

// What the reference says about one field: its unit, range and default (the member's default in
// file units, unless the field states its own text; "*required*" when it must be given).
template <typename T>
KeyDoc DocOf(const NumberField<T>& field) {
  std::ostringstream value;
  value << T{}.*field.member / field.file_to_si;
  return {field.key, UnitOfKey(field.key), RangeText(field.sign, field.range),
          field.default_text ? field.default_text : !field.optional ? "*required*" : value.str()};
}
template <typename T>
std::vector<KeyDoc> DocsOf(const FieldTable<T>& fields) {
  std::vector<KeyDoc> docs;
  for (const NumberField<T>& field : fields) docs.push_back(DocOf(field));
  return docs;
}

// One number of `f` (file units): of `sign`, and within `range` when there is one.
inline double ReadNumber(const YamlFields& f, const std::string& key, Sign sign,
                         const limits::Range* range = nullptr) {
  const double v = sign == Sign::kPositive      ? f.Positive(key)
                   : sign == Sign::kNonNegative ? f.NonNegative(key)
                                                : f.Number(key);
  if (range) limits::Require(*range, v, f.file(), f.Path(key));
  return v;
}

// A number read on its own rather than into a table's struct: the key, the sign and range it must
// have (file units) and the reference's default. The loader reads it with ReadNumber(f, key) and the
// reference documents it with DocOf(key), so both state the same check.
struct NumberKey {
  const char* key;
  Sign sign = Sign::kAny;
  const limits::Range* range = nullptr;
  const char* default_text = nullptr;  // what an absent key means; none: `default_value`
  double default_value = std::numeric_limits<double>::quiet_NaN();  // file units; NaN, no text: required
};
inline double ReadNumber(const YamlFields& f, const NumberKey& k) { return ReadNumber(f, k.key, k.sign, k.range); }
inline double ReadNumberOr(const YamlFields& f, const NumberKey& k, double fallback) {
  return f.Has(k.key) ? ReadNumber(f, k) : fallback;
}
inline KeyDoc DocOf(const NumberKey& k) {
  std::ostringstream value;
  value << k.default_value;
  return {k.key, UnitOfKey(k.key), RangeText(k.sign, k.range),
          k.default_text ? k.default_text : std::isnan(k.default_value) ? "*required*" : value.str()};
}
// A block's keys (in order) documented plainly, except those `numbers` describe.
inline std::vector<KeyDoc> DocsWith(const std::vector<std::string>& keys, std::initializer_list<NumberKey> numbers) {
  std::vector<KeyDoc> docs;
  for (const std::string& key : keys) {
    const NumberKey* number = nullptr;
    for (const NumberKey& n : numbers)
      if (key == n.key) number = &n;
    docs.push_back(number ? DocOf(*number) : PlainKeyDoc(key));
  }
  return docs;
}

// Reads every field `f` has (a missing required field fails) into `out`.
template <typename T>
void ReadFields(const YamlFields& f, const FieldTable<T>& fields, T& out) {
  for (const NumberField<T>& field : fields) {
    if (field.optional && !f.Has(field.key)) continue;
    out.*field.member = ReadNumber(f, field.key, field.sign, field.range) * field.file_to_si;
  }
}

// Writes the fields of `value` in table order (file units), leaving out the defaults of the
// fields that say so.
template <typename T>
void WriteFields(YAML::Emitter& y, const FieldTable<T>& fields, const T& value) {
  const T defaults{};
  for (const NumberField<T>& field : fields) {
    if (field.omit_default && value.*field.member == defaults.*field.member) continue;
    y << YAML::Key << field.key << YAML::Value << value.*field.member / field.file_to_si;
  }
}

// Checks that `f` states every field of `fields` as `expected` has it, in file units and to the
// last bit (a derived value a resolved copy writes for its reader, read back against the file it
// was derived from). `what` names that file in the message.
template <typename T>
void RequireFieldsMatch(const YamlFields& f, const FieldTable<T>& fields, const T& expected, const std::string& what) {
  for (const NumberField<T>& field : fields) {
    const double want = expected.*field.member / field.file_to_si;
    if (field.optional && field.omit_default && !f.Has(field.key) && expected.*field.member == T{}.*field.member)
      continue;
    const double given = f.Number(field.key);
    if (given != want) {
      std::ostringstream message;
      message << std::setprecision(17) << "is " << given << " but " << what << " gives " << want;
      f.Fail(field.key, message.str());
    }
  }
}

}  // namespace touchdown::io
