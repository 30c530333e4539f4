#pragma once
// The grains carried with the pad in 3D (rft/effect_terms.h, docs/model_gap.md): the two forms of
// added mass the literature uses, over the pad's submerged footprint A (a = sqrt(A / pi)).
//
// `added_mass`, the cone grown with depth: the 45-degree cone under the footprint, grown to the
// penetration until whole,
//
//   m_a = c_a rho (pi/3) a^2 min(d, a) = (c_a rho / 3) A min(d, a),
//
// `added_mass_plug`, the dead zone under a flat pad: the whole cone of height a, attached to the
// pad over a fixed formation depth d_f from first contact,
//
//   m_p = c_p rho (pi/3) a^3 min(1, d / d_f) = (c_p rho / 3) A a min(1, d / d_f).
//
// The plug is the cone with its formation length a replaced by d_f. A plug gained at an instant
// would be an impulse (an event in each of the rig, the free pad and the lander); over d_f the
// accretion force v dm/dt stays finite and hands the momentum m_p v to the grains while the pad
// sinks d_f, which tends to that impulse as d_f -> 0. d_f = kPlugFormationDepthM (below).
//
// A is the horizontal projection of the pad's submerged downward-facing surface
// (ContactWrench::footprint_area_m2; pi a(d)^2 for an axisymmetric pad), d the pad's penetration
// (deepest point). The time derivatives follow from those of A and d
// (ContactWrench::footprint_area_rate_m2_s, penetration_rate_m_s); for a level axisymmetric pad
// moving straight down at v they are m'(d) v. Pure functions, SI units.
#include "rft/pad_level_terms.h"

namespace touchdown::rft {

// The plug's formation depth d_f: an assumption, not read from a source. It stands for "a few
// grain layers" of a fine simulant (its grains well under a millimetre), the depth over which a dead
// zone of grains locks under a flat intruder. What matters is that it lies far below the strokes of
// the drops (10 to 50 mm): the momentum handed over is m_p v0 to within d_f / stroke, so a fitted
// c_p hardly depends on the exact value (EffectRig.PlugTendsToTheInstantImpulse: the final depth
// moves 1.7 um between d_f = 1 mm and the instant impact).
inline constexpr double kPlugFormationDepthM = 1e-3;

struct EntrainedMass {
  double mass_kg = 0.0;      // m
  double rate_kg_s = 0.0;    // dm/dt
};

// density_kg_m3 = c_a rho. Zero for d <= 0 or A <= 0.
EntrainedMass EntrainedCone(double density_kg_m3, double penetration_m, double penetration_rate_m_s,
                            double footprint_area_m2, double footprint_area_rate_m2_s);
// density_kg_m3 = c_p rho, formation_depth_m = d_f > 0. Zero for d <= 0 or A <= 0.
EntrainedMass EntrainedPlug(double density_kg_m3, double formation_depth_m, double penetration_m,
                            double penetration_rate_m_s, double footprint_area_m2, double footprint_area_rate_m2_s);
// Both forms of `terms` (PadLevelTerms::added_mass_density_kg_m3, plug_density_kg_m3), the plug at
// kPlugFormationDepthM; with no plug exactly EntrainedCone.
EntrainedMass EntrainedGrains(const PadLevelTerms& terms, double penetration_m, double penetration_rate_m_s,
                              double footprint_area_m2, double footprint_area_rate_m2_s);

}  // namespace touchdown::rft
