// The Lambert-W stop depth of Katsuragi & Durian's law against the law itself: s(d) = 0, s > 0
// before it, and an independent integration of m dv/dt = m g - m v^2/d1 - k z.
#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/validation/katsuragi_durian.h"

namespace touchdown::validation {
namespace {

const KatsuragiDurianParameters kKdLaw{0.087, 1040.0, 9.81};

// Classic RK4 on (z, v) with a fine step until v changes sign; the root by linear interpolation.
double IntegratedStopDepth(const KatsuragiDurianParameters& p, double v0) {
  const auto accel = [&](double z, double v) { return p.gravity_m_s2 - v * v / p.d1_m - p.k_over_m_s2 * z; };
  double z = 0.0, v = v0;
  const double dt = 1e-6;
  for (int i = 0; i < 10000000; ++i) {
    const double k1z = v, k1v = accel(z, v);
    const double k2z = v + 0.5 * dt * k1v, k2v = accel(z + 0.5 * dt * k1z, v + 0.5 * dt * k1v);
    const double k3z = v + 0.5 * dt * k2v, k3v = accel(z + 0.5 * dt * k2z, v + 0.5 * dt * k2v);
    const double k4z = v + dt * k3v, k4v = accel(z + dt * k3z, v + dt * k3v);
    const double zn = z + dt / 6 * (k1z + 2 * k2z + 2 * k3z + k4z), vn = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (vn <= 0.0 && i > 0) return z + (zn - z) * v / (v - vn);
    z = zn, v = vn;
  }
  return NAN;
}

TEST(KatsuragiDurianLaw, StopDepthIsTheRootOfTheSpeedSquared) {
  for (const double v0 : {0.0, 0.1879, 0.657, 1.7155, 4.0354}) {
    const double d = KatsuragiDurianStopDepth(kKdLaw, v0);
    EXPECT_NEAR(KatsuragiDurianSpeedSquared(kKdLaw, v0, d), 0.0, 1e-12) << v0;
    for (int i = 1; i < 100; ++i) EXPECT_GT(KatsuragiDurianSpeedSquared(kKdLaw, v0, d * i / 100.0), 0.0) << v0;
  }
}

TEST(KatsuragiDurianLaw, StopDepthMatchesAnIntegrationOfTheForceLaw) {
  for (const double v0 : {0.0, 0.3194, 1.1719, 4.0354}) {
    const double d = KatsuragiDurianStopDepth(kKdLaw, v0);
    EXPECT_NEAR(d, IntegratedStopDepth(kKdLaw, v0), 1e-8) << v0;
  }
}

TEST(KatsuragiDurianLaw, FromRestWithLittleDragItIsTwiceTheStaticDepth) {
  // d1 >> depth: m z'' = m g - k z from rest stops at 2 g m / k; the drag's share is of order
  // v^2 / (g d1) ~ 1e-5 at d1 = 100 m.
  const KatsuragiDurianParameters spring{100.0, 1040.0, 9.81};
  EXPECT_NEAR(KatsuragiDurianStopDepth(spring, 0.0), 2.0 * 9.81 / 1040.0, 2e-6);
  EXPECT_LT(KatsuragiDurianStopDepth(spring, 0.0), 2.0 * 9.81 / 1040.0);  // drag only shortens the stroke
}

TEST(KatsuragiDurianLaw, UncertaintyIsHalfTheCornerRange) {
  const DepthWithUncertainty r = KatsuragiDurianStopDepthRange(kKdLaw, 0.007, 10.0, 2.0);
  const double a = KatsuragiDurianStopDepth({0.080, 1050.0, 9.81}, 2.0);
  const double b = KatsuragiDurianStopDepth({0.094, 1030.0, 9.81}, 2.0);
  EXPECT_DOUBLE_EQ(r.depth_m, KatsuragiDurianStopDepth(kKdLaw, 2.0));
  EXPECT_NEAR(r.half_range_m, 0.5 * (b - a), 1e-15);
  EXPECT_THROW(KatsuragiDurianStopDepth({0.0, 1040.0, 9.81}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace touchdown::validation
