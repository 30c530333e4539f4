#include "rft/entrained_mass.h"

#include <cmath>
#include <numbers>

namespace touchdown::rft {

EntrainedMass EntrainedCone(double density, double d, double area, double area_rate) {
  EntrainedMass out;
  if (!(density > 0.0) || !(d > 0.0) || !(area > 0.0)) return out;
  const double a = std::sqrt(area / std::numbers::pi);
  if (d < a) {
    out.mass_kg = density / 3.0 * area * d;
    out.slope_kg_m = density / 3.0 * (area_rate * d + area);
  } else {
    // d(A a)/dd = A' a + A a' with a' = A' / (2 pi a): 3/2 A' a.
    out.mass_kg = density / 3.0 * area * a;
    out.slope_kg_m = density / 3.0 * 1.5 * area_rate * a;
  }
  return out;
}

}  // namespace touchdown::rft
