#pragma once
// What the contact needs to know about one soil: the stress law of its elements and the terms
// that act on the pad as a whole, held side by side (built by rft/stress_law_3d_factory.h).
#include <cmath>
#include <memory>
#include <string>

#include "rft/pad_level_terms.h"
#include "rft/stress_law_3d.h"

namespace touchdown::rft {

struct SoilContactModel {
  std::shared_ptr<const StressLaw3D> law;  // shared: a terrain's soil maps copy it
  PadLevelTerms pad_terms;
  // Janosi-Hanamoto's K [m] when the law has a shear that mobilises with the pad's shear
  // displacement j (a Bekker soil with c > 0 or phi > 0), else 0: the pad then carries j as a state
  // (the free pad, the lander's pads) and the contact scales the shear by 1 - exp(-j / K).
  double janosi_K_m = 0.0;

  bool has_janosi_shear() const { return janosi_K_m > 0.0; }
  // 1 - exp(-j / K) (PadKinematics::shear_mobilisation); j >= 0.
  double ShearMobilisation(double shear_displacement_m) const {
    return -std::expm1(-shear_displacement_m / janosi_K_m);
  }

  // The law's name with the active pad-level terms appended ("li2013+rate_damping+compaction_peak"),
  // as outputs name the model that ran.
  std::string name() const {
    std::string out(law->name());
    // Bekker's z^n is the bekker law's own depth law, not the depth_exponent effect.
    if (pad_terms.has_power_depth() && law->kind() != LawKind::kBekker) out += "+depth_exponent";
    if (pad_terms.has_compaction()) out += "+compaction_peak";
    if (pad_terms.added_mass_density_kg_m3 > 0.0) out += "+added_mass";
    if (pad_terms.plug_density_kg_m3 > 0.0) out += "+added_mass_plug";
    return out;
  }
};

}  // namespace touchdown::rft
