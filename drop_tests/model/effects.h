#pragma once
// The effect library: physically named terms that quasi-static RFT leaves out (physics.md,
// section 4), each switchable in every simulation (rig drops; free drops and the lander in its 3D
// form, below) and fitted by `touchdown diagnose` on rig drops.
// The ids are part of the interface (model files, diagnosis.json, the command line).
// A new effect of the stress kind is one file, rft/effects/<name>_effect.cpp
// (rft/effects/effect_definition.h); it joins this library by itself.
//
// The terms themselves (rft::EffectTerms, the flat numbers every simulation reads) are in
// rft/effect_terms.h; this file holds what a file and a fit know about them (ids, parameter keys,
// units, ranges, fitting scales). Each simulation applies them in its own form:
//  - the rig (1 DOF, axisymmetric pad): lander/pad/effect_soil_response.h, forces from the
//    integrals I_k(d) of cos^k(beta) over the submerged leading surface;
//  - free drops and the lander (the per-element contact of rft/contact_wrench.h): the contact
//    model of model::MakeContactModel (drop_tests/model/contact_model.h), the per-element terms as StressLaw3D decorators
//    (inertial_drag rft/dynamic_term.h, rate_damping rft/rate_damping_term.h, gas_cushion
//    rft/gas_cushion_term.h, beds in air only) and depth_exponent, compaction_peak and
//    added_mass and added_mass_plug as the pad-level terms of rft/pad_level_terms.h. For a level axisymmetric pad
//    moving straight down each 3D form is the rig's.
// depth_exponent's z_ref is 10 mm fixed, the depth scale of the paper's drops, so zeta keeps its
// meaning at that depth. sensor_offset never changes the physics: the recorded penetration reads
// dz more than the true one, and the recorded t = 0 lies dt after the true touchdown.
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rft/effect_terms.h"
#include "rft/effects/effect_definition.h"

namespace touchdown::model {

// The effects of the library, in its order. Files and the command line name them by EffectInfo::id
// ("rate_damping"); past that edge (FindEffect) code dispatches on this.
enum class EffectId {
  kInertialDrag,
  kRateDamping,
  kAddedMass,
  kAddedMassPlug,
  kCompactionPeak,
  kDepthExponent,
  kGasCushion,
  kSensorOffset,
  // The registered effects (rft/effects/, one file each) follow, the i-th of
  // rft::RegisteredEffects() as EffectId(int(kRegisteredBegin) + i): code past the file edge treats
  // them through their definition, never by name.
  kRegisteredBegin,
};

// One parameter of an effect as a file and a fit see it (its key, unit, range, neutral value and
// fitting scales): rft/effects/effect_definition.h.
using EffectParameterInfo = rft::EffectParameter;

struct EffectInfo {
  EffectId kind;
  std::string id;          // its name in files, outputs and on the command line
  std::string form;        // one line, the documented form
  std::vector<EffectParameterInfo> parameters;
  bool air_only = false;         // acts only on drops in air
  bool measurement_only = false;  // changes what the sensors record, not the physics
  bool needs_bulk_density = false;  // its force scales with the soil's bulk density rho
  // A registered effect's definition (rft/effects/), null for the built-in ones.
  const rft::EffectDefinition* registered = nullptr;
};

// The library, in EffectId's order (EffectLibrary()[int(kind)].kind == kind): the built-in effects,
// then the registered ones.
const std::vector<EffectInfo>& EffectLibrary();
// Throws InputError naming `context` if `id` is not in the library.
const EffectInfo& FindEffect(const std::string& id, const std::string& context = "");
const EffectInfo& FindEffect(EffectId kind);

// An effect with its parameter values (SI, in the order of EffectInfo::parameters).
struct Effect {
  std::string id;
  std::vector<double> values;
};

// Throws InputError (naming `context`) on a value outside its range or a repeated id.
rft::EffectTerms MakeEffectTerms(const std::vector<Effect>& effects, const std::string& context = "");

// The effects that act (parameters not all neutral: c = 0, p = 1, chi = c_g = 0, ...), by id in
// library order. A listed effect with neutral parameters changes nothing and is not active.
std::vector<std::string> ActiveEffects(const rft::EffectTerms& terms);
std::vector<EffectId> ActiveEffectIds(const rft::EffectTerms& terms);
// The active effects a drop does not apply to its physics, with the reason: sensor_offset always
// (measurement only: `compare` applies it to the simulated traces it compares with measured
// ones), gas_cushion when the drop is not in air.
std::vector<std::pair<std::string, std::string>> EffectsNotApplied(const rft::EffectTerms& terms, bool in_air);

// Per effect, the [low, high] (SI) of each parameter in EffectInfo order (a fit's confidence
// intervals; informational). Reading and writing the `effects:` mapping of a model file:
// drop_tests/model/effects_yaml.h (private to .cpp files).
using EffectIntervals = std::vector<std::vector<std::pair<double, double>>>;

}  // namespace touchdown::model
