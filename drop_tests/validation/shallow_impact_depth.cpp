#include "drop_tests/validation/shallow_impact_depth.h"

#include <cmath>
#include <algorithm>
#include <stdexcept>

namespace touchdown::validation {

double ShallowImpactLength(const ShallowImpactParameters& p) {
  if (!(p.prefactor > 0.0) || !(p.friction_coefficient > 0.0) || !(p.sphere_density_kg_m3 > 0.0) ||
      !(p.medium_density_kg_m3 > 0.0) || !(p.sphere_diameter_m > 0.0))
    throw std::invalid_argument("ShallowImpactLength: every parameter must be positive");
  return p.prefactor / p.friction_coefficient * std::sqrt(p.sphere_density_kg_m3 / p.medium_density_kg_m3) *
         std::cbrt(p.sphere_diameter_m * p.sphere_diameter_m);
}

double ShallowImpactDepth(const ShallowImpactParameters& p, double drop_height_m) {
  if (!(drop_height_m >= 0.0)) throw std::invalid_argument("ShallowImpactDepth: negative drop height");
  const double length = ShallowImpactLength(p);
  const double a = length * length * length;
  // t^3 + P t + Q = 0 with P = -a, Q = -a h.
  const double half_q = 0.5 * a * drop_height_m;
  const double discriminant = half_q * half_q - a * a * a / 27.0;
  if (discriminant > 0.0) {
    const double s = std::sqrt(discriminant);
    return std::cbrt(half_q + s) + std::cbrt(half_q - s);
  }
  // Three real roots: the largest, 2 sqrt(a/3) cos(acos((3h/2) sqrt(3/a)) / 3).
  const double c = std::min(1.0, 1.5 * drop_height_m * std::sqrt(3.0 / a));
  return 2.0 * std::sqrt(a / 3.0) * std::cos(std::acos(c) / 3.0);
}

}  // namespace touchdown::validation
