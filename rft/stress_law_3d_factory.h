#pragma once
// Builds the 3D stress law a soil asks for, scaled to the gravity of the run.
#include <memory>
#include <string_view>

#include "rft/effect_terms.h"
#include "rft/law_kind.h"
#include "rft/soil.h"
#include "rft/soil_contact_model.h"
#include "rft/stress_law_3d.h"
#include "rft/surface_elements.h"

namespace touchdown::rft {

// law: kLi2013 (Li 2013 via Treers et al. 2021; needs zeta, scaled to gravity_m_s2 from the
// soil's reference gravity) or kAgarwal2023 (needs bulk density and internal friction angle;
// xi_n = rho g (894 mu^3 - 386 mu^2 + 89 mu), mu = tan(phi), and mu_surf): the quasi-static law
// only (a soil's own dynamic term is an effect term, WithSoilDynamicTerm). Throws InputError
// on missing/invalid soil data, naming the soil and the field.
// kBekker (rft/bekker_law.h) needs the pad's dimension b, `bekker_plate_b_m` (BekkerPlateB; > 0),
// and the soil's bekker block; gravity does not enter (Bekker's moduli do not scale with g).
std::unique_ptr<StressLaw3D> MakeStressLaw3D(LawKind law, const SoilParameters& soil,
                                             double gravity_m_s2, double bekker_plate_b_m = 0.0);
// The effect terms a drop on `soil` runs under: `terms` with the soil's own dynamic term
// (dynamic_term, dynamic_lambda) as inertial_drag, unless `terms` has an inertial term of its own
// (lambda > 0, or stated by a model: inertial_replaces_soil, even at lambda 0). The soil's term is lambda rho_c (v.n)^2; as
// inertial_drag (lambda' rho (v.n)^2, rho the bulk density) it is lambda' = lambda rho_c / rho.
// Every simulation (the rig's response, the 3D contact) takes its terms from here, so a soil's
// dynamic term acts alike on the rig, free pads and the lander.
EffectTerms WithSoilDynamicTerm(const EffectTerms& terms, const SoilParameters& soil);
// Checks a soil's bekker block (what kBekker needs), naming the soil and the field on an error.
void RequireBekkerParameters(const SoilParameters& soil);
// Whether `soil` can run on `law` at `gravity_m_s2`: every check MakeStressLaw3D makes of the soil
// and the gravity (InputError naming the soil and the field), without a pad. The one soil-law
// check at load time (a lander's ground, a drop request), before a pad's b is known.
void CheckSoilTakesLaw(LawKind law, const SoilParameters& soil, double gravity_m_s2);

// The soil's law with the effect terms (rft/effect_terms.h) in their 3D form. The per-element
// terms wrap the law above:
//   inertial_lambda > 0  DynamicTermLaw (rft/dynamic_term.h), lambda rho (v.n)^2 on leading
//                        elements with rho the soil's bulk density (the soil's own dynamic
//                        term is folded in first, WithSoilDynamicTerm);
//   damping_c_N_s_m3     RateDampingLaw (rft/rate_damping_term.h), c (v.n) on leading elements;
//   gas_chi, gas_c       GasCushionLaw (rft/gas_cushion_term.h), stress per depth x (1 - chi)
//                        plus c_g (v.n); the caller passes them only for a bed in air.
// The pad-level terms go to SoilContactModel::pad_terms (rft/pad_level_terms.h): the depth law
// z_ref (z / z_ref)^p, the compaction transient k_c, d_c and the added mass c_a rho (rho the
// soil's bulk density). A term whose parameters are all neutral changes nothing, so with
// neutral terms the law is exactly the one above. The sensor offsets are not physics and are
// ignored. Throws InputError naming the soil when a term's value is invalid or a term needs the
// bulk density and the soil has none.
// kBekker: the depth law is Bekker's z^n ({n, 1 m}), so the depth_exponent term does not apply
// (InputError); its plate dimension b is the pad's, BekkerPlateB(*pad_surface), computed here for
// every caller (an InputError names the soil when a bekker law gets no pad). Other laws ignore the pad.
SoilContactModel MakeSoilContactModel(LawKind law, const SoilParameters& soil, double gravity_m_s2,
                                      const EffectTerms& terms, const SurfaceElements* pad_surface = nullptr);

}  // namespace touchdown::rft
