#pragma once
// The effect terms: physically named terms that quasi-static RFT leaves out, as plain numbers
// (SI), flattened for the hot loops of every simulation. The forms and their derivation are in
// docs/physics.md, section 4; in short, with v.n the normal velocity of a leading element:
//
//   inertial_drag    stress lambda rho (v.n)^2                                 lambda [-]
//   rate_damping     stress c (v.n)                                            c [N s/m^3]
//   added_mass       grains carried with the pad, m_a = c_a rho V (the entrained cone of
//                    rft/entrained_mass.h), entering as d(m_a v)/dt          c_a [-]
//   added_mass_plug  the dead zone under a flat pad, m_p = c_p rho (pi/3) a^3 of the footprint
//                    radius a, attached over the first d_f of the stroke
//                    (rft/entrained_mass.h), entering as d(m_p v)/dt         c_p [-]
//   compaction_peak  stress k_c (v.n)^2, the pad's force scaled by exp(-z_pad / d_c), z_pad the
//                    pad's penetration (the bed compacts in the first d_c)   k_c [kg/m^3], d_c [m]
//   depth_exponent   stress per depth weighted by z_ref (z / z_ref)^p instead of z
//                    (p = 1: the linear law of RFT)                          p [-], z_ref [m]
//   gas_cushion      beds in air only: stress per depth x (1 - chi), plus c_g (v.n)
//                                                                            chi [-], c_g [N s/m^3]
//   sensor_offset    measurement only: the recorded penetration reads dz more than the true one,
//                    and the recorded t = 0 lies dt after the true touchdown dz [m], dt [s]
//
//   registered       the effects of rft/effects/ (one file each: cohesion, ...), their values
//                    below by index in RegisteredEffects()
//
// rho is the soil's bulk density. Defaults: every term neutral (quasi-static RFT).
#include <array>

#include "rft/effects/effect_definition.h"

namespace touchdown::rft {

// A registered effect's values (SI, in EffectDefinition::parameters order); off unless active.
struct RegisteredEffectValues {
  bool active = false;
  std::array<double, kMaxEffectParameters> values{};
};

struct EffectTerms {
  double inertial_lambda = 0.0;      // lambda [-]
  double damping_c_N_s_m3 = 0.0;     // c [N s/m^3]
  double added_mass_ca = 0.0;        // c_a [-]
  double added_mass_plug_cp = 0.0;   // c_p [-]
  double compaction_k_kg_m3 = 0.0;   // k_c [kg/m^3]
  double compaction_depth_m = 1.0;   // d_c [m], > 0
  double depth_exponent = 1.0;       // p [-], > 0; 1 is the linear law, computed as such
  double depth_reference_m = 0.01;   // z_ref [m], > 0
  double gas_chi = 0.0;              // chi [-], in [0, 1)
  double gas_c_N_s_m3 = 0.0;         // c_g [N s/m^3]
  double sensor_dz_m = 0.0;          // dz [m]
  double sensor_dt_s = 0.0;          // dt [s]
  // inertial_drag is stated (by a model or a fit), even at lambda 0: it replaces the soil's own
  // dynamic term (rft/stress_law_3d_factory.h WithSoilDynamicTerm) instead of adding to it.
  bool inertial_replaces_soil = false;
  // The registered effects (rft/effects/), by index in RegisteredEffects().
  std::array<RegisteredEffectValues, kMaxRegisteredEffects> registered{};
  // Needs the soil's bulk density (inertial_drag, added_mass, added_mass_plug).
  bool NeedsDensity() const {
    if (inertial_lambda != 0.0 || added_mass_ca != 0.0 || added_mass_plug_cp != 0.0) return true;
    for (size_t i = 0; i < RegisteredEffects().size(); ++i)
      if (registered[i].active && RegisteredEffects()[i].needs_bulk_density) return true;
    return false;
  }
  bool HasRegistered() const {
    for (const RegisteredEffectValues& r : registered)
      if (r.active) return true;
    return false;
  }
  bool HasDepthExponent() const { return depth_exponent != 1.0; }
  bool HasSensorOffset() const { return sensor_dz_m != 0.0 || sensor_dt_s != 0.0; }
};

}  // namespace touchdown::rft
