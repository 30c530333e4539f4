#pragma once
// The gas around a granular bed: vacuum (the paper's chamber pumped down) or air. Files and the
// command line name it "vacuum" or "air"; ParseAtmosphere reads those names where they come in,
// AtmosphereName writes them back out, and everything in between holds the enum.
#include <optional>
#include <string_view>

namespace touchdown::rft {

enum class Atmosphere { kVacuum, kAir };

inline const char* AtmosphereName(Atmosphere a) { return a == Atmosphere::kAir ? "air" : "vacuum"; }

// nullopt for any other name (the caller reports it, naming its file and field).
inline std::optional<Atmosphere> ParseAtmosphere(std::string_view name) {
  if (name == "vacuum") return Atmosphere::kVacuum;
  if (name == "air") return Atmosphere::kAir;
  return std::nullopt;
}

}  // namespace touchdown::rft
