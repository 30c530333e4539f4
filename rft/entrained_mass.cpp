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

}  // namespace touchdown::rft
