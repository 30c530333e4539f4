#pragma once
// The one factory of a soil's 3D contact model (stress law and pad-level terms) above rft: free
// drops, their VTK frames, `force`, calibrate's mesh-pad laws and the lander's soils all build it
// here, so a model file's overrides and the effect terms reach every 3D contact alike.
// rft::MakeSoilContactModel (rft/stress_law_3d_factory.h) is the physics underneath.
#include <optional>
#include <string>

#include "drop_tests/model/model_file.h"
#include "rft/effect_terms.h"
#include "rft/law_kind.h"
#include "rft/soil.h"
#include "rft/soil_contact_model.h"
#include "rft/surface_elements.h"

namespace touchdown::model {

struct ContactModelRequest {
  std::optional<rft::LawKind> law{};  // none: the soil's own (rft_law_3d)
  // The soil as the run sees it; its atmosphere decides whether gas_cushion acts (air only).
  rft::SoilParameters soil{};
  double gravity_m_s2 = 0.0;  // zeta is scaled to it from the soil's reference gravity
  // The model file (null: none): its soil override (zeta, dynamic_lambda; ApplyModel) and its
  // effect terms (ModelEffectTerms). With a model, `effects` must be neutral.
  const ModelFile* model = nullptr;
  rft::EffectTerms effects{};  // the effect terms of a run without a model file
  std::string effects_source{};  // where `effects` came from, for error messages
  // The pad, whose footprint gives the bekker law its plate dimension b (rft::BekkerPlateB);
  // other laws ignore it.
  const rft::SurfaceElements* pad_surface = nullptr;
};

// The contact model: the law with the active effect terms in their 3D form (model/effects.h:
// inertial_drag, rate_damping and gas_cushion as stress decorators, depth_exponent,
// compaction_peak, added_mass and added_mass_plug as pad-level terms). Throws InputError naming the
// soil and the model file (or `effects_source`) when an effect needs the bulk density and the soil
// has none, or a value is invalid.
rft::SoilContactModel MakeContactModel(const ContactModelRequest& request);

}  // namespace touchdown::model
