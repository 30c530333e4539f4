#include "rft/entrained_mass.h"

#include <cmath>
#include <numbers>

namespace touchdown::rft {

EntrainedMass EntrainedCone(double density, double d, double d_dot, double area, double area_dot) {
  EntrainedMass out;
  if (!(density > 0.0) || !(d > 0.0) || !(area > 0.0)) return out;
  const double a = std::sqrt(area / std::numbers::pi);
  if (d < a) {
    out.mass_kg = density / 3.0 * area * d;
    out.rate_kg_s = density / 3.0 * (area_dot * d + area * d_dot);
  } else {
    // d(A a)/dt = A' a + A a' with a' = A' / (2 pi a): 3/2 A' a.
    out.mass_kg = density / 3.0 * area * a;
    out.rate_kg_s = density / 3.0 * 1.5 * area_dot * a;
  }
  return out;
}

EntrainedMass EntrainedPlug(double density, double d_f, double d, double d_dot, double area, double area_dot) {
  EntrainedMass out;
  if (!(density > 0.0) || !(d > 0.0) || !(area > 0.0)) return out;
  const double a = std::sqrt(area / std::numbers::pi);
  const double whole = density / 3.0 * area * a, whole_rate = density / 3.0 * 1.5 * area_dot * a;
  if (d < d_f) {
    out.mass_kg = whole * (d / d_f);
    out.rate_kg_s = whole_rate * (d / d_f) + whole * (d_dot / d_f);
  } else {
    out.mass_kg = whole;
    out.rate_kg_s = whole_rate;
  }
  return out;
}

EntrainedMass EntrainedGrains(const PadLevelTerms& t, double d, double d_dot, double area, double area_dot) {
  EntrainedMass out = EntrainedCone(t.added_mass_density_kg_m3, d, d_dot, area, area_dot);
  if (t.plug_density_kg_m3 > 0.0) {
    const EntrainedMass plug = EntrainedPlug(t.plug_density_kg_m3, kPlugFormationDepthM, d, d_dot, area, area_dot);
    out.mass_kg += plug.mass_kg;
    out.rate_kg_s += plug.rate_kg_s;
  }
  return out;
}

}  // namespace touchdown::rft
