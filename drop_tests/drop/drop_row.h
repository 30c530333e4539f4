#pragma once
// What a drop states about itself, in SI, wherever it comes from: a dataset row
// (dataset::DropRowOf), a sweep point (sweep::SweepDropParams is one), a targets file, the command
// line (drop::RequestConditions). drop::DropConditions is one with how to run it (free body, law,
// effects); drop::DropConditionsFor makes those from a row. The one type the stated conditions
// travel in, so none is copied field by field on the way to the resolver (drop_setup.h).
#include <optional>

#include "rft/atmosphere.h"
#include "rft/gravity_constants.h"

namespace touchdown::drop {

struct DropRow {
  double impact_speed_m_s = 0.0;
  std::optional<double> mass_kg;              // default: the pad's mass
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  std::optional<double> zeta_N_m3;            // overrides the soil's zeta (at its reference gravity)
  std::optional<rft::Atmosphere> atmosphere;  // a dataset row states it; default: the soil's
  double tilt_rad = 0.0;                      // at release, about the drop's tilt axis
  double horizontal_speed_m_s = 0.0;          // along +x of the world
};

}  // namespace touchdown::drop
