#pragma once
// The effect library's `added_mass` in 3D (drop_tests/effects.h): the grains carried with the pad
// are the 45-degree cone under its submerged footprint, grown to the penetration until whole,
//
//   m_a = c_a rho (pi/3) a^2 min(d, a) = (c_a rho / 3) A min(d, a),    a = sqrt(A / pi),
//
// with A the footprint: the horizontal projection of the pad's submerged downward-facing surface
// (ContactWrench::footprint_area_m2; pi a(d)^2 for an axisymmetric pad, a(d) its radius at the
// surface, so the rig's m_a(d) exactly), and d the pad's penetration (deepest point). The slope
// dm_a/dd is taken along a downward translation of the pad (ContactWrench::footprint_area_rate_m;
// for a level axisymmetric pad the rig's AddedMassSlope). Pure function, SI units.
namespace touchdown::rft {

struct EntrainedMass {
  double mass_kg = 0.0;      // m_a
  double slope_kg_m = 0.0;   // dm_a/dd along a downward translation
};

// density_kg_m3 = c_a rho; footprint_area_rate_m2_m = dA/dd. Zero for d <= 0 or A <= 0.
EntrainedMass EntrainedCone(double density_kg_m3, double penetration_m, double footprint_area_m2,
                            double footprint_area_rate_m2_m);

}  // namespace touchdown::rft
