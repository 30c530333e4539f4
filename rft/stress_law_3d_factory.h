#pragma once
// Builds the 3D stress law a soil asks for, scaled to the gravity of the run.
#include <memory>
#include <string_view>

#include "rft/soil.h"
#include "rft/stress_law_3d.h"

namespace touchdown::rft {

// law: "li2013" (Li 2013 via Treers et al. 2021; needs zeta, scaled to gravity_m_s2 from the
// soil's reference gravity) or "agarwal2023" (needs bulk density and internal friction angle;
// xi_n = rho g (894 mu^3 - 386 mu^2 + 89 mu), mu = tan(phi), and mu_surf). When the soil's
// dynamic_term is on, the law is wrapped in DynamicTermLaw (lambda, rho_c). Throws InputError
// on an unknown law name or missing/invalid soil data, naming the soil and the field.
std::unique_ptr<StressLaw3D> MakeStressLaw3D(std::string_view law, const SoilParameters& soil,
                                             double gravity_m_s2);

// The effect terms in their 3D form (the effect library, drop_tests/model/effects.h), as
// decorators around the law above:
//   inertial_lambda > 0  DynamicTermLaw (rft/dynamic_term.h), lambda rho (v.n)^2 on leading
//                        elements with rho = inertial_density_kg_m3 (0: the soil's bulk density);
//                        it replaces the soil's own dynamic_term;
//   damping_c_N_s_m3     RateDampingLaw (rft/rate_damping_term.h), c (v.n) on leading elements;
//   gas_chi, gas_c       GasCushionLaw (rft/gas_cushion_term.h), stress per depth x (1 - chi)
//                        plus c_g (v.n); the caller passes them only for a bed in air.
//   depth_exponent != 1  DepthExponentLaw (rft/pad_effect_terms.h): z_ref (z/z_ref)^p depth law;
//   compaction_k > 0     CompactionPeakLaw: k_c (v.n)^2 on leading elements, x exp(-z_pad/d_c);
//   added_mass_ca > 0    AddedMassLaw: c_a rho (rho = the soil's bulk density) of the entrained
//                        cone, applied by the free drop and the lander (rft/entrained_mass.h).
// A term whose parameters are all 0 adds no decorator, so the law is exactly the one above.
struct EffectTerms3D {
  double inertial_lambda = 0.0;          // [-]
  double inertial_density_kg_m3 = 0.0;   // [kg/m^3]
  double damping_c_N_s_m3 = 0.0;         // [N s/m^3]
  double gas_chi = 0.0;                  // [-], in [0, 1)
  double gas_c_N_s_m3 = 0.0;             // [N s/m^3]
  double depth_exponent = 1.0;           // p [-], > 0
  double depth_reference_m = 0.01;       // z_ref [m], > 0
  double compaction_k_kg_m3 = 0.0;       // k_c [kg/m^3]
  double compaction_depth_m = 1.0;       // d_c [m], > 0
  double added_mass_ca = 0.0;            // c_a [-]
};
// Throws InputError naming the soil when a term's value is invalid or the inertial term has no
// density.
std::unique_ptr<StressLaw3D> MakeStressLaw3D(std::string_view law, const SoilParameters& soil,
                                             double gravity_m_s2, const EffectTerms3D& terms);

}  // namespace touchdown::rft
