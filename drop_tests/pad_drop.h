#pragma once
// One single-footpad rig drop of a catalogued pad on a catalogued soil.
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/catalog.h"
#include "drop_tests/effects.h"
#include "drop_tests/rig_drop.h"

namespace touchdown::drop {

struct DropConditions {
  double impact_speed_m_s = 0.0;
  std::optional<double> mass_kg;        // default: the pad's mass
  double gravity_m_s2 = 9.81;
  std::optional<double> zeta_N_m3;      // overrides the soil's zeta (at its reference gravity)
  std::optional<std::string> atmosphere;  // "vacuum" or "air"; default: the soil's
  EffectTerms effects;                  // default: none (quasi-static RFT)
};

struct PadDrop {
  PadSpec pad;  // as loaded, without its 3D body (the rig drop does not use it)
  rft::SoilParameters soil;
  DropConditions conditions;
  double mass_kg = 0.0;          // resolved
  double zeta_effective_N_m3 = 0.0;  // at the drop's gravity
  RigDropResult result;
};

// Throws InputError if a condition is out of range (naming `context`).
void ValidateConditions(const DropConditions& c, const std::string& context);
PadDrop RunPadDrop(const PadSpec& pad, const rft::SoilParameters& soil, const DropConditions& conditions,
                   const RigDropOptions& options = {});

// The JSON summary `touchdown drop` prints (SI values, unit-suffixed keys).
nlohmann::json SummaryJson(const PadDrop& drop);
// Writes the trace as CSV with the header t_s,penetration_m,velocity_m_s,force_N.
void WriteTraceCsv(const RigDropResult& result, const std::string& path);

}  // namespace touchdown::drop
