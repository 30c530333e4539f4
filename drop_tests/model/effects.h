#pragma once
// The effect library: physically named terms that quasi-static RFT leaves out (physics.md,
// section 4), each switchable in every simulation (rig drops; free drops and the lander in its 3D
// form, below) and fitted by `touchdown diagnose` on rig drops.
// The ids are part of the interface (model files, diagnosis.json, the command line).
//
// For straight-down motion an element of attack angle beta has v.n = v cos(beta) (n outward,
// v the downward speed); a normal stress s on it pushes up with s cos(beta) dA. With
// I_k(d) = integral of cos^k(beta) dA over the submerged leading surface
// (AxisymmetricIntrusion::CosinePowerIntegral), the terms add to the soil reaction:
//
//   inertial_drag    lambda rho (v.n)^2         F += lambda rho v^2 I_3(d)           lambda [-]
//   rate_damping     c (v.n)                    F += c v I_2(d)                      c [N s/m^3]
//   added_mass       grains carried with the pad, m_a(d) = c_a rho V(d), d(m_a v)/dt  c_a [-]
//                    V(d) = (pi/3) a(d)^2 min(d, a(d)): the 45-degree cone of grains under the
//                    submerged footprint (radius a), grown to the penetration depth until whole;
//                    continuous from m_a(0) = 0, so touchdown never sees an infinite force
//   compaction_peak  k_c (v.n)^2 exp(-d / d_c)  F += k_c v^2 exp(-d/d_c) I_3(d)     k_c [kg/m^3], d_c [m]
//                    (d = the pad's penetration: the bed under the pad compacts during the first
//                    d_c of the stroke, then the transient is gone)
//   depth_exponent   zeta alpha z_ref (z/z_ref)^p instead of zeta alpha z              p [-]
//                    (z_ref = 10 mm fixed, the depth scale of the paper's drops, so zeta keeps
//                    its meaning at that depth)
//   gas_cushion      only drops in air: zeta -> (1 - chi) zeta, and F += c_g v I_2(d) chi [-], c_g [N s/m^3]
//   sensor_offset    measurement only: the recorded penetration reads dz more than the true
//                    one, and the recorded t = 0 lies dt after the true touchdown (late trigger)
//                                                                                    dz [m], dt [s]
//
// Every velocity term vanishes at rest, so the static capacity is the quasi-static force (with
// the depth law and the gas cushion applied).
//
// In 3D (free drop, lander: the per-element contact of rft/contact_wrench.h) every physical term
// is a StressLaw3D decorator (MakeEffectLaw3D below): inertial_drag (rft/dynamic_term.h),
// rate_damping (rft/rate_damping_term.h), gas_cushion (rft/gas_cushion_term.h, beds in air only),
// and the pad-level terms of rft/pad_effect_terms.h: depth_exponent (z^p integrated exactly per
// triangle by the contact), compaction_peak (k_c (v.n)^2 per leading element, scaled by
// exp(-z_pad/d_c) with the pad's penetration z_pad) and added_mass (the entrained cone of
// rft/entrained_mass.h on the footprint, added to the pad's vertical inertia by the free drop and
// the lander). For a level axisymmetric pad moving straight down each 3D form is the rig's.
// sensor_offset never changes the physics.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lander/pad/rig_drop.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/soil.h"
#include "rft/stress_law_3d.h"

namespace touchdown::model {

// One parameter of an effect as a file and a fit see it.
struct EffectParameterInfo {
  std::string key;         // in files, unit-suffixed: "c_N_s_m3", "d_c_mm"
  std::string symbol;      // in the documentation: "c", "d_c"
  std::string unit;        // SI unit of the value held in memory
  double file_to_si = 1.0;  // value_SI = value_file * file_to_si
  double lower = 0.0, upper = 0.0;  // admissible range (SI)
  double scale = 1.0;       // a typical magnitude (SI), for fitting
  double start = 0.0;       // starting value of a fit (SI)
  std::vector<double> scan;  // if given, a fit first picks the best of these starts (SI)
};

struct EffectInfo {
  std::string id;
  std::string form;        // one line, the documented form
  std::vector<EffectParameterInfo> parameters;
  bool air_only = false;         // acts only on drops in air
  bool measurement_only = false;  // changes what the sensors record, not the physics
};

// The library, in a fixed order.
const std::vector<EffectInfo>& EffectLibrary();
// Throws InputError naming `context` if `id` is not in the library.
const EffectInfo& FindEffect(const std::string& id, const std::string& context = "");

// An effect with its parameter values (SI, in the order of EffectInfo::parameters).
struct Effect {
  std::string id;
  std::vector<double> values;
};

// All effect terms of a model, flattened for the hot loop. Defaults: quasi-static RFT.
struct EffectTerms {
  double inertial_lambda = 0.0;
  double damping_c_N_s_m3 = 0.0;
  double added_mass_ca = 0.0;
  double compaction_k_kg_m3 = 0.0;
  double compaction_depth_m = 1.0;
  std::optional<double> depth_exponent;
  double depth_reference_m = 0.01;
  double gas_chi = 0.0;
  double gas_c_N_s_m3 = 0.0;
  double sensor_dz_m = 0.0;
  double sensor_dt_s = 0.0;
  // Needs the soil's bulk density (inertial_drag, added_mass).
  bool NeedsDensity() const { return inertial_lambda != 0.0 || added_mass_ca != 0.0; }
  bool HasSensorOffset() const { return sensor_dz_m != 0.0 || sensor_dt_s != 0.0; }
};

// Throws InputError (naming `context`) on a value outside its range or a repeated id.
EffectTerms MakeEffectTerms(const std::vector<Effect>& effects, const std::string& context = "");

// The effects that act (parameters not all neutral: c = 0, p = 1, chi = c_g = 0, ...), by id in
// library order. A listed effect with neutral parameters changes nothing and is not active.
std::vector<std::string> ActiveEffects(const EffectTerms& terms);
// The active effects a drop does not apply to its physics, with the reason: sensor_offset always
// (measurement only: `compare` applies it to the simulated traces it compares with measured
// ones), gas_cushion when the drop is not in air.
std::vector<std::pair<std::string, std::string>> EffectsNotApplied(const EffectTerms& terms, bool in_air);
// The 3D stress law `law` of `soil` (zeta as given, scaled to gravity) with the active effect
// terms (rft/stress_law_3d_factory.h EffectTerms3D): inertial_drag and added_mass (rho = the
// soil's bulk density, as in the rig), rate_damping, compaction_peak, depth_exponent, and
// gas_cushion when `in_air`. Throws InputError naming the soil and `model_source` when an effect
// needs the bulk density and the soil has none.
std::unique_ptr<rft::StressLaw3D> MakeEffectLaw3D(std::string_view law, const rft::SoilParameters& soil,
                                                  double gravity_m_s2, const EffectTerms& terms, bool in_air,
                                                  const std::string& model_source);

// Per effect, the [low, high] (SI) of each parameter in EffectInfo order (a fit's confidence
// intervals; informational). Reading and writing the `effects:` mapping of a model file:
// drop_tests/model/effects_yaml.h (private to .cpp files).
using EffectIntervals = std::vector<std::vector<std::pair<double, double>>>;

// The rig's soil response with effect terms, for one pad, soil and atmosphere.
struct SoilResponseInputs {
  double zeta_N_m3 = 0.0;           // at the drop's gravity
  double bulk_density_kg_m3 = 0.0;  // needed by inertial_drag and added_mass
  bool in_air = false;
  EffectTerms terms;
};

class EffectSoilResponse final : public pad::VerticalSoilResponse {
 public:
  // Throws InputError if an effect needs the bulk density and it is 0.
  EffectSoilResponse(const geom::AxisymmetricIntrusion& pad, const SoilResponseInputs& inputs);
  double Force(double depth_m, double speed_down_m_s) const override;
  double AddedMass(double depth_m) const override;
  double AddedMassSlope(double depth_m) const override;
  double StaticCapacity(double depth_m) const override { return QuasiStaticForce(depth_m); }
  double QuasiStaticForce(double depth_m) const;

 private:
  const geom::AxisymmetricIntrusion& pad_;
  SoilResponseInputs in_;
  double zeta_qs_;  // with the gas cushion applied
  double i2_coefficient_;  // c (+ c_g in air)
};

// What the rig's sensors record at recorded time t_rec [s] for a simulated drop, with the
// sensor_offset applied: the true state at t_rec + dt, penetration + dz. Before touchdown the
// pad is in free fall (penetration v0 t + g t^2 / 2 < 0, force 0); after the trace ends it stays
// at the last sample. Linear interpolation between samples.
struct RecordedSample {
  double penetration_m = 0.0;
  double force_N = 0.0;
};
RecordedSample RecordedAt(const pad::RigDropResult& result, double gravity_m_s2, const EffectTerms& terms, double t_rec);

}  // namespace touchdown::model
