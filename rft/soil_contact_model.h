#pragma once
// What the contact needs to know about one soil: the stress law of its elements and the terms
// that act on the pad as a whole, held side by side (built by rft/stress_law_3d_factory.h).
#include <memory>
#include <string>

#include "rft/pad_level_terms.h"
#include "rft/stress_law_3d.h"

namespace touchdown::rft {

struct SoilContactModel {
  std::shared_ptr<const StressLaw3D> law;  // shared: a terrain's soil maps copy it
  PadLevelTerms pad_terms;

  // The law's name with the active pad-level terms appended ("li2013+rate_damping+compaction_peak"),
  // as outputs name the model that ran.
  std::string name() const {
    std::string out(law->name());
    // Bekker's z^n is the bekker law's own depth law, not the depth_exponent effect.
    if (pad_terms.has_power_depth() && law->name() != "bekker") out += "+depth_exponent";
    if (pad_terms.has_compaction()) out += "+compaction_peak";
    if (pad_terms.has_added_mass()) out += "+added_mass";
    return out;
  }
};

}  // namespace touchdown::rft
