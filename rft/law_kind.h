#pragma once
// Which 3D stress law a soil uses. Files and the command line name it ("li2013", "agarwal2023", "bekker");
// past that edge it is this enum (rft/stress_law_3d_factory.h builds the law).
#include <string>
#include <string_view>

namespace touchdown::rft {

enum class LawKind {
  kLi2013,       // Li 2013 via Treers et al. 2021 (rft/li2013_3d.h)
  kAgarwal2023,  // Agarwal et al. 2023 (rft/agarwal2023.h)
  kBekker,       // Bekker-Wong-Janosi terramechanics (rft/bekker_law.h), not RFT
};

// The name in files and on the command line.
std::string_view LawKindName(LawKind law);
// Parses that name. Throws InputError naming `where` and `field` on any other.
LawKind ParseLawKind(std::string_view name, const std::string& where, const std::string& field);

}  // namespace touchdown::rft
