#pragma once
// The stop depth of Katsuragi & Durian's measured force law (Nat. Phys. 3, 420, 2007) for a sphere
// hitting the bed at v0: m dv/dt = m g - m v^2 / d1 - k z, z down from the surface.
// With s = v^2 as a function of depth, ds/dz = 2 g - 2 s / d1 - 2 (k/m) z, so
//   s(z) = A + B z + (v0^2 - A) exp(-2 z / d1),  A = g d1 + (k/m) d1^2 / 2,  B = -(k/m) d1,
// and the stop depth, the first z > 0 with s(z) = 0, is a Lambert-W expression: with
// y = z + A/B, (2y/d1) exp(2y/d1) = -(2 (v0^2 - A) / (B d1)) exp(2A / (B d1)).
// Pure functions, no state.
#include "rft/gravity_constants.h"

namespace touchdown::validation {

struct KatsuragiDurianParameters {
  double d1_m = 0.0;          // inertial drag length
  double k_over_m_s2 = 0.0;   // friction slope per unit mass [1/s^2]
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
};

// v^2 at depth z on the way down [m^2/s^2].
double KatsuragiDurianSpeedSquared(const KatsuragiDurianParameters& p, double v0_m_s, double depth_m);
// The stop depth [m] (Lambert W, both real branches; the smallest positive root). Throws
// std::invalid_argument on non-positive d1 or k/m, or a negative v0.
double KatsuragiDurianStopDepth(const KatsuragiDurianParameters& p, double v0_m_s);

// The stop depth and its half-range over the four corners d1 +- dd1, k/m +- dk (the stated
// uncertainties of the fit).
struct DepthWithUncertainty {
  double depth_m = 0.0, half_range_m = 0.0;
};
DepthWithUncertainty KatsuragiDurianStopDepthRange(const KatsuragiDurianParameters& p, double d1_uncertainty_m,
                                                   double k_over_m_uncertainty_s2, double v0_m_s);

}  // namespace touchdown::validation
