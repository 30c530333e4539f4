#include "rft/law_kind.h"

#include "rft/input_error.h"

namespace touchdown::rft {

std::string_view LawKindName(LawKind law) {
  switch (law) {
    case LawKind::kLi2013:
      return "li2013";
    case LawKind::kAgarwal2023:
      return "agarwal2023";
    case LawKind::kBekker:
      return "bekker";
  }
  return "li2013";  // not reached: every enumerator is named above
}

LawKind ParseLawKind(std::string_view name, const std::string& where, const std::string& field) {
  if (name == "li2013") return LawKind::kLi2013;
  if (name == "agarwal2023") return LawKind::kAgarwal2023;
  if (name == "bekker") return LawKind::kBekker;
  throw MakeInputError(where, field,
                       "unknown 3D stress law '" + std::string(name) + "' (expected li2013, agarwal2023 or bekker)");
}

}  // namespace touchdown::rft
