#pragma once
// The registered effects (rft/effects/, one file each) in their 3D form, as one decorator around
// any StressLaw3D: on a submerged element it adds each active effect's depth-independent stress
// (EffectDefinition::element_stress_Pa) to the inner law's DynamicStress. The wrapped law's other
// stresses are kept unchanged.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "rft/effect_terms.h"
#include "rft/forwarding_law_3d.h"

namespace touchdown::rft {

class RegisteredEffectsLaw final : public ForwardingLaw3D {
 public:
  // The active registered effects of `terms`, with the soil's bulk density (those that need it
  // were checked for it by the caller). Throws std::invalid_argument on a null law.
  RegisteredEffectsLaw(std::unique_ptr<StressLaw3D> inner, const EffectTerms& terms, double bulk_density_kg_m3);
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  bool has_dynamic_stress() const override { return true; }

 private:
  struct Active {
    const EffectDefinition* effect;
    std::array<double, kMaxEffectParameters> values;
  };
  std::vector<Active> active_;  // filled once; DynamicStress only reads it
  double rho_;
};

}  // namespace touchdown::rft
