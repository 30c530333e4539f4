// cohesion: the soil's cohesion c, which quasi-static RFT (a cohesionless law, stress per depth
// zeta z) leaves out. On every submerged leading element it adds a normal stress independent of
// depth and speed, the cohesive part of a surface footing's bearing capacity,
//
//   sigma_c = -N_c c n,    N_c = pi + 2 (Prandtl's factor)
//
// so a level flat pad of area A carries N_c c A more from the first millimetre on, at rest too
// (the rig's static capacity). N_c = pi + 2 is the cohesion's own bearing factor (a weightless,
// frictionless soil): friction's share of the bearing capacity is RFT's own depth stress already.
// Bearing theory with friction couples the two (N_c(phi) = (N_q - 1) cot(phi), about 90 at the
// 42 degrees of lunar regolith); that coupling is left out, so a c fitted here is an effective
// cohesion, c_eff = c N_c(phi) / (pi + 2) (docs/model_gap.md).
// Lunar regolith: c = 0.1 to 1 kPa (Carrier, Olhoeft and Mendell 1991, Lunar Sourcebook, ch. 9);
// Surveyor 3's surface sampler bounds it below 1 N/cm^2 (10 kPa). The range admits 0 to 100 kPa.
#include <numbers>

#include "rft/effects/effect_definition.h"

namespace touchdown::rft::effects {

namespace {
constexpr double kBearingFactor = std::numbers::pi + 2.0;  // N_c, Prandtl

double RigForce(const double* v, const RigPoint& p) {
  return p.depth_m > 0.0 ? kBearingFactor * v[0] * p.I1_m2 : 0.0;
}

// The contact calls this on leading elements (n.v >= 0) and fades it out on faces turning away
// (rft/contact_internal.h kTrailingBand), so the stress itself does not look at v: a hard switch
// at n.v = 0 would make the force jump.
Eigen::Vector3d ElementStress(const double* v, double /*rho*/, const Eigen::Vector3d& n_W,
                              const Eigen::Vector3d& /*v_W*/) {
  return (-kBearingFactor * v[0]) * n_W;
}
}  // namespace

EffectDefinition cohesion_effect() {
  EffectDefinition e;
  e.id = "cohesion";
  e.form = "stress N_c c on leading elements, N_c = pi + 2, at rest too: F += N_c c I1(d)";
  // key, symbol, SI unit, file -> SI, range, fitting scale and start, scan, neutral, file unit
  e.parameters = {{"c_kPa", "c", "Pa", 1e3, 0.0, 1e5, 500.0, 500.0, {}, 0.0, "kPa"}};
  e.rig_force_N = RigForce;
  e.element_stress_Pa = ElementStress;
  e.docs_rig_row = "| `cohesion` | stress `N_c c`, `N_c = pi + 2`, at rest too: `F += N_c c I_1(d)` | `c_kPa` [kPa] |";
  e.docs_3d_row = "| cohesion | -N_c c n on leading elements, over the submerged area | `rft/effects/cohesion_effect.cpp` |";
  return e;
}

}  // namespace touchdown::rft::effects
