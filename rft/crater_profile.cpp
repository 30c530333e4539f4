#include "rft/crater_profile.h"

#include <cmath>

namespace touchdown::rft {

CraterShape DegradedCraterShape(double degradation) {
  CraterShape s;
  s.depth_to_diameter *= 1.0 - degradation;
  s.rim_height_to_diameter *= 1.0 - degradation;
  return s;
}

double CraterHeight(const CraterShape& shape, double diameter_m, double r_m) {
  const double R = 0.5 * diameter_m;
  const double d = shape.depth_to_diameter * diameter_m, h = shape.rim_height_to_diameter * diameter_m;
  const double rho = std::abs(r_m) / R;
  if (rho <= 1.0) return h - d * (1.0 - rho * rho);
  return h * std::pow(rho, -shape.ejecta_exponent);
}

}  // namespace touchdown::rft
