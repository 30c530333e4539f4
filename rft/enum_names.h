#pragma once
// One names table per enum: the names files, outputs and the command line give an enum's values,
// in one constexpr array beside the enum, and the ways through it (a value's name; the value of a
// name, or one line refusing any other: "must be a, b or c, got 'd'"). Code past the YAML edge
// holds the enum; only these tables hold its names.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rft/input_error.h"

namespace touchdown {

template <typename E>
struct EnumName {
  E value;
  const char* name;
};

// The name of `value` (every value of the enum is in its table; "?" would be a table's bug).
template <typename E, std::size_t N>
constexpr const char* NameIn(const std::array<EnumName<E>, N>& table, E value) {
  for (const EnumName<E>& e : table)
    if (e.value == value) return e.name;
  return "?";
}

// The value named `text`, or nullopt.
template <typename E, std::size_t N>
std::optional<E> FindName(const std::array<EnumName<E>, N>& table, std::string_view text) {
  for (const EnumName<E>& e : table)
    if (text == e.name) return e.value;
  return std::nullopt;
}

// The names in table order, "a, b or c", for messages and help.
template <typename E, std::size_t N>
std::string NameChoices(const std::array<EnumName<E>, N>& table) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) out += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(table[i].name);
  return out;
}

// The names in table order, as a list (a command line's choices).
template <typename E, std::size_t N>
std::vector<std::string> NameList(const std::array<EnumName<E>, N>& table) {
  std::vector<std::string> names;
  for (const EnumName<E>& e : table) names.push_back(e.name);
  return names;
}

// The value named `text`; an InputError naming `where` and `field` for any other text.
template <typename E, std::size_t N>
E ParseName(const std::array<EnumName<E>, N>& table, const std::string& text, const std::string& where,
            const std::string& field) {
  if (const std::optional<E> v = FindName(table, text)) return *v;
  throw MakeInputError(where, field, "must be " + NameChoices(table) + ", got '" + text + "'");
}

}  // namespace touchdown
