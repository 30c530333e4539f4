#include "rft/registered_effects_law.h"

#include <utility>

namespace touchdown::rft {

namespace {
std::string Suffix(const EffectTerms& terms) {
  std::string s;
  for (size_t i = 0; i < RegisteredEffects().size(); ++i)
    if (terms.registered[i].active) s += (s.empty() ? "" : "+") + RegisteredEffects()[i].id;
  return s;
}
}  // namespace

RegisteredEffectsLaw::RegisteredEffectsLaw(std::unique_ptr<StressLaw3D> inner, const EffectTerms& terms,
                                           double bulk_density_kg_m3)
    : ForwardingLaw3D(std::move(inner), Suffix(terms)), rho_(bulk_density_kg_m3) {
  for (size_t i = 0; i < RegisteredEffects().size(); ++i)
    if (terms.registered[i].active) active_.push_back({&RegisteredEffects()[i], terms.registered[i].values});
}

Eigen::Vector3d RegisteredEffectsLaw::DynamicStress(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  Eigen::Vector3d s = inner_->DynamicStress(n, v);
  for (const Active& a : active_) s += a.effect->element_stress_Pa(a.values.data(), rho_, n, v);
  return s;
}

}  // namespace touchdown::rft
