#pragma once
// The effect term `added_mass` in 3D (rft/effect_terms.h, docs/physics.md section 4): the grains
// carried with the pad are the 45-degree cone under its submerged footprint, grown to the penetration until whole,
//
//   m_a = c_a rho (pi/3) a^2 min(d, a) = (c_a rho / 3) A min(d, a),    a = sqrt(A / pi),
//
// with A the footprint: the horizontal projection of the pad's submerged downward-facing surface
// (ContactWrench::footprint_area_m2; pi a(d)^2 for an axisymmetric pad, a(d) its radius at the
// surface, so the axisymmetric form m_a(d) exactly), and d the pad's penetration (deepest point). Its time
// derivative follows from those of A and d (ContactWrench::footprint_area_rate_m2_s,
// penetration_rate_m_s); for a level axisymmetric pad moving straight down at v it is
// m_a'(d) v. Pure function, SI units.
namespace touchdown::rft {

struct EntrainedMass {
  double mass_kg = 0.0;      // m_a
  double rate_kg_s = 0.0;    // dm_a/dt
};

// density_kg_m3 = c_a rho. Zero for d <= 0 or A <= 0.
EntrainedMass EntrainedCone(double density_kg_m3, double penetration_m, double penetration_rate_m_s,
                            double footprint_area_m2, double footprint_area_rate_m2_s);

}  // namespace touchdown::rft
