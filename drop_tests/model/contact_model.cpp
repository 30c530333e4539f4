#include "drop_tests/model/contact_model.h"

#include <stdexcept>

#include "drop_tests/model/effects.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::model {

rft::SoilContactModel MakeContactModel(const ContactModelRequest& r) {
  if (r.model && !ActiveEffectIds(r.effects).empty())
    throw std::invalid_argument("MakeContactModel: effect terms given with a model file (the model's are used)");
  const rft::SoilParameters soil = r.model ? ApplyModel(*r.model, r.soil) : r.soil;
  rft::EffectTerms terms = r.model ? ModelEffectTerms(*r.model) : r.effects;
  const std::string source =
      !r.model ? r.effects_source : r.model->source.empty() ? "model " + r.model->name : r.model->source;
  if (soil.atmosphere != rft::Atmosphere::kAir) {  // beds in air only
    terms.gas_chi = terms.gas_c_N_s_m3 = 0.0;
    for (size_t i = 0; i < rft::RegisteredEffects().size(); ++i)
      if (rft::RegisteredEffects()[i].air_only) terms.registered[i].active = false;
  }
  if (terms.NeedsDensity() && !(soil.bulk_density_kg_m3 > 0.0))
    throw MakeInputError(soil.name, "bulk_density_kg_m3",
                         "the soil must state its bulk density for inertial_drag, added_mass and added_mass_plug (model " +
                             source + ")");
  return rft::MakeSoilContactModel(r.law.value_or(soil.rft_law_3d), soil, r.gravity_m_s2, terms, r.pad_surface);
}

}  // namespace touchdown::model
