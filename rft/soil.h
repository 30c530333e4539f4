#pragma once
// Fixed parameters of a granular bed (model data, never per-step state). SI inside.
#include <string>

#include "rft/atmosphere.h"
#include "rft/bekker_parameters.h"
#include "rft/gravity_constants.h"
#include "rft/gravity_scaling.h"
#include "rft/law_kind.h"

namespace touchdown::rft {

struct SoilParameters {
  std::string name;
  // RFT scaling factor zeta [N/m^3]: vertical stress per unit depth on a horizontal plate
  // pushed straight down, at the gravity `reference_gravity_m_s2` it was measured at.
  double zeta_N_m3 = 0.0;
  double reference_gravity_m_s2 = kEarthGravity_m_s2;
  double bulk_density_kg_m3 = 0.0;        // [kg/m^3], 0 when unknown
  double internal_friction_angle_rad = 0.0;  // [rad], 0 when unknown
  Atmosphere atmosphere = Atmosphere::kVacuum;

  // 3D laws (rft/stress_law_3d_factory.h). All defaulted, so 2D users are unaffected.
  LawKind rft_law_3d = LawKind::kLi2013;  // preferred 3D law (kBekker: the soil's `law: bekker`)
  // Bekker-Wong-Janosi parameters (rft/bekker_law.h); used by the bekker law only (no zeta then).
  BekkerParameters bekker;
  // Intruder-surface friction coefficient mu_surf [-] of Agarwal et al. 2023 (only that law).
  // 0.4 is an assumption (a typical sand-on-metal value), not a measured pad value.
  double surface_friction_coefficient = 0.4;
  // Dynamic RFT (Agarwal et al., Sci. Adv. 2021): adds lambda rho_c (v.n)^2 [Pa] on leading
  // elements. lambda [-] (order one; 1.0 is an assumption until fitted), rho_c [kg/m^3]
  // (0 = use bulk_density_kg_m3).
  bool dynamic_term = false;
  double dynamic_lambda = 1.0;
  double dynamic_density_kg_m3 = 0.0;

  // How zeta changes with gravity (rft/gravity_scaling.h): lithostatic (zeta proportional to g,
  // the default) or none.
  GravityScaling gravity_scaling = GravityScaling::kLithostatic;

  double ZetaAtGravity(double gravity_m_s2) const {
    if (gravity_scaling == GravityScaling::kNone) return zeta_N_m3;
    return zeta_N_m3 * gravity_m_s2 / reference_gravity_m_s2;
  }
  // Sets zeta so that ZetaAtGravity(gravity_m_s2) is `zeta_at_gravity_N_m3` (a zeta fitted or
  // given at another gravity than this soil's reference).
  void SetZetaAtGravity(double zeta_at_gravity_N_m3, double gravity_m_s2) {
    zeta_N_m3 = gravity_scaling == GravityScaling::kNone ? zeta_at_gravity_N_m3
                                                         : zeta_at_gravity_N_m3 * reference_gravity_m_s2 / gravity_m_s2;
  }
};

// Agarwal, Goldman & Kamrin (PNAS 2023) material scaling of the vertical plate stress per
// unit depth: xi_n = rho g (894 mu^3 - 386 mu^2 + 89 mu), mu the internal friction coefficient.
inline double AgarwalScalingXi(double bulk_density_kg_m3, double gravity_m_s2, double mu) {
  return bulk_density_kg_m3 * gravity_m_s2 * (894.0 * mu * mu * mu - 386.0 * mu * mu + 89.0 * mu);
}

}  // namespace touchdown::rft
