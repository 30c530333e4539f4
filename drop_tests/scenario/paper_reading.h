#pragma once
// The reading of Sutoh et al. 2017's LP/CP sentence (Sec. II-C2) that a paper check compares with.
// The transcription drops every zero and the sentence parses several ways, so a check against it
// says which reading it takes (docs/calibration_targets.md, "Reading the LP/CP sentence").
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "drop_tests/formats/yaml_fields.h"

namespace touchdown::scenario {

enum class PaperReading {
  kR1,   // LP/CP 3.9 in air, 1.9 in vacuum
  kR1z,  // LP/CP 3.9 in air, 1.09 in vacuum (a dropped zero restored): the default
  kR2,   // air/vacuum 3.9 on CP, 1.9 on LP (literal; contradicts the paper's conclusions)
  kR3,   // air/vacuum 1.9 on CP, 3.9 on LP ("respectively" swapped)
};

inline constexpr std::array<std::pair<PaperReading, std::string_view>, 4> kPaperReadingNames{
    {{PaperReading::kR1, "R1"}, {PaperReading::kR1z, "R1z"}, {PaperReading::kR2, "R2"}, {PaperReading::kR3, "R3"}}};

inline std::string_view PaperReadingName(PaperReading r) {
  for (const auto& [reading, name] : kPaperReadingNames)
    if (reading == r) return name;
  return "?";
}

// `reading` of a paper check, if given; an unknown name fails naming the field and the valid names.
inline std::optional<PaperReading> ReadPaperReading(const io::YamlFields& f) {
  if (!f.Has("reading")) return std::nullopt;
  const std::string given = f.String("reading");
  for (const auto& [reading, name] : kPaperReadingNames)
    if (given == name) return reading;
  f.Fail("reading", "must be R1, R1z, R2 or R3 (docs/calibration_targets.md), got '" + given + "'");
}

}  // namespace touchdown::scenario
