#include "rft/law_kind.h"

#include "rft/input_error.h"

namespace touchdown::rft {

std::string_view LawKindName(LawKind law) {
  switch (law) {
    case LawKind::kLi2013:
      return "li2013";
    case LawKind::kAgarwal2023:
      return "agarwal2023";
  }
  return "li2013";  // not reached: every enumerator is named above
}

LawKind ParseLawKind(std::string_view name, const std::string& where, const std::string& field) {
  if (name == "li2013") return LawKind::kLi2013;
  if (name == "agarwal2023") return LawKind::kAgarwal2023;
  throw MakeInputError(where, field,
                       "unknown 3D stress law '" + std::string(name) + "' (expected li2013 or agarwal2023)");
}

}  // namespace touchdown::rft
