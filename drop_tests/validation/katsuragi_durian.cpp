#include "drop_tests/validation/katsuragi_durian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/special_functions/lambert_w.hpp>

namespace touchdown::validation {

namespace {
struct Coefficients {
  double A, B;
};
Coefficients CoefficientsOf(const KatsuragiDurianParameters& p) {
  return {p.gravity_m_s2 * p.d1_m + 0.5 * p.k_over_m_s2 * p.d1_m * p.d1_m, -p.k_over_m_s2 * p.d1_m};
}
}  // namespace

double KatsuragiDurianSpeedSquared(const KatsuragiDurianParameters& p, double v0_m_s, double depth_m) {
  const Coefficients c = CoefficientsOf(p);
  return c.A + c.B * depth_m + (v0_m_s * v0_m_s - c.A) * std::exp(-2.0 * depth_m / p.d1_m);
}

double KatsuragiDurianStopDepth(const KatsuragiDurianParameters& p, double v0_m_s) {
  if (!(p.d1_m > 0.0) || !(p.k_over_m_s2 > 0.0) || !(v0_m_s >= 0.0))
    throw std::invalid_argument("Katsuragi-Durian law: d1 and k/m must be positive, v0 non-negative");
  const Coefficients c = CoefficientsOf(p);
  const double C = v0_m_s * v0_m_s - c.A;
  const double shift = c.A / c.B;  // z = y - A/B
  const double q = 2.0 * c.A / (c.B * p.d1_m);
  // The argument of W; computed as -(2C/(B d1)) exp(q) (q < -1 always, so exp(q) is small).
  const double w_arg = -(2.0 * C / (c.B * p.d1_m)) * std::exp(q);
  double best = std::numeric_limits<double>::infinity();
  const auto consider = [&](double w) {
    const double z = 0.5 * p.d1_m * w - shift;
    // z = 0 is the trivial root of a drop from rest (v0 = 0); keep the positive one.
    if (z > 1e-12 * p.d1_m) best = std::min(best, z);
  };
  const double branch_point = -std::exp(-1.0);
  if (w_arg >= branch_point) consider(boost::math::lambert_w0(w_arg));
  if (w_arg < 0.0 && w_arg >= branch_point) consider(boost::math::lambert_wm1(w_arg));
  if (!std::isfinite(best)) throw std::invalid_argument("Katsuragi-Durian law: no stop depth");
  return best;
}

DepthWithUncertainty KatsuragiDurianStopDepthRange(const KatsuragiDurianParameters& p, double d1_uncertainty_m,
                                                   double k_over_m_uncertainty_s2, double v0_m_s) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double sd : {-1.0, 1.0}) {
    for (const double sk : {-1.0, 1.0}) {
      KatsuragiDurianParameters corner = p;
      corner.d1_m += sd * d1_uncertainty_m;
      corner.k_over_m_s2 += sk * k_over_m_uncertainty_s2;
      const double z = KatsuragiDurianStopDepth(corner, v0_m_s);
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
  }
  return {KatsuragiDurianStopDepth(p, v0_m_s), 0.5 * (hi - lo)};
}

}  // namespace touchdown::validation
