// Vertical intrusion of axisymmetric pads against closed forms and an independent quadrature.
#include "footpad_geom/axisymmetric_intrusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "rft/input_error.h"

namespace touchdown::geom {
namespace {

constexpr double kZeta = 2.0e6;  // N/m^3
const rft::Li2013Law kLaw;

// alpha_z(pi/2, pi/2) of the generic fit, computed from its coefficients.
double WallAlpha() { return rft::Li2013Alpha(std::numbers::pi / 2, std::numbers::pi / 2).z; }

TEST(FootpadFlat, ForceIsBottomPlusSideWallWhileShallow) {
  const double r = 0.05, h = 0.016;
  const AxisymmetricIntrusion pad(MakeFlatProfile(r, h), kLaw);
  for (double d : {0.0, 1e-4, 0.003, 0.008, 0.016}) {
    const double closed = kZeta * (std::numbers::pi * r * r * d + WallAlpha() * std::numbers::pi * r * d * d);
    EXPECT_NEAR(pad.VerticalForce(d, kZeta), closed, 1e-12 * closed + 1e-12) << "d " << d;
  }
  // The published coefficient value of the wall term.
  EXPECT_NEAR(WallAlpha(), 0.128, 5e-4);
}

TEST(FootpadFlat, DeeperThanThicknessOnlyTheProfileCarries) {
  // d > h: the wall spans depths d - h .. d; the top face trails and carries nothing.
  const double r = 0.05, h = 0.016;
  const AxisymmetricIntrusion pad(MakeFlatProfile(r, h), kLaw);
  for (double d : {0.017, 0.03, 0.1}) {
    const double closed = kZeta * (std::numbers::pi * r * r * d + WallAlpha() * std::numbers::pi * r * (2 * d * h - h * h));
    EXPECT_NEAR(pad.VerticalForce(d, kZeta), closed, 1e-12 * closed) << "d " << d;
  }
}

TEST(FootpadFlat, ForceIsContinuousAndMonotoneInDepth) {
  const AxisymmetricIntrusion pad(MakeChamferProfile(0.05, 0.016, 0.004), kLaw);
  double previous = 0.0;
  for (double d = 1e-5; d < 0.05; d += 1e-5) {
    const double f = pad.VerticalForce(d, kZeta);
    EXPECT_GE(f, previous);
    EXPECT_LT(f - previous, 0.02 * f + 1.0) << "jump at d " << d;
    previous = f;
  }
}

// Independent quadrature of the paper's integral for a smooth bottom u(x): composite
// Gauss-Legendre in x over the submerged part, ds = sqrt(1 + u'^2) dx, plus the wall.
double QuadratureForce(const std::function<double(double)>& u, const std::function<double(double)>& du, double r,
                       double h, double d) {
  // the submerged radius: u(x) < d (u increasing)
  double lo = 0.0, hi = r;
  if (u(r) > d) {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (u(mid) < d ? lo : hi) = mid;
    }
  } else {
    lo = r;
  }
  const double x_max = lo;
  const double gx[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const int n = 4000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double a = x_max * i / n, b = x_max * (i + 1) / n;
    for (int k = 0; k < 3; ++k) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * gx[k];
      const double slope = du(x);
      const double alpha = rft::Li2013Alpha(std::atan(slope), std::numbers::pi / 2).z;
      sum += 0.5 * (b - a) * gw[k] * alpha * (d - u(x)) * 2 * std::numbers::pi * x * std::sqrt(1 + slope * slope);
    }
  }
  // The vertical side wall from u(r) to h at radius r, below the surface where depth > 0.
  const double top = std::min(h, d), bottom = u(r);
  if (top > bottom) sum += WallAlpha() * 2 * std::numbers::pi * r * 0.5 * ((d - bottom) * (d - bottom) - (d - top) * (d - top));
  return kZeta * sum;
}

TEST(FootpadChamfer, MatchesIndependentQuadrature) {
  const double r = 0.05, h = 0.016, c = 0.004;
  const AxisymmetricIntrusion pad(MakeChamferProfile(r, h, c), kLaw);
  auto u = [&](double x) { return x < r - c ? 0.0 : x - (r - c); };
  auto du = [&](double x) { return x < r - c ? 0.0 : 1.0; };
  for (double d : {0.001, 0.004, 0.01, 0.02}) {
    const double q = QuadratureForce(u, du, r, h, d);
    EXPECT_NEAR(pad.VerticalForce(d, kZeta), q, 2e-4 * q) << "d " << d;
  }
}

TEST(FootpadCurved, MatchesIndependentQuadratureAndConvergesWithRings) {
  const double r = 0.05, h = 0.016, a0 = 0.002, a1 = 40.0;
  auto u = [&](double x) { return a0 * std::expm1(a1 * x); };
  auto du = [&](double x) { return a0 * a1 * std::exp(a1 * x); };
  const double d = 0.008;
  const double q = QuadratureForce(u, du, r, h, d);
  double previous_error = INFINITY;
  for (int rings : {25, 50, 100, 200, 400, 800}) {
    const AxisymmetricIntrusion pad(MakeExponentialProfile(r, h, a0, a1, rings), kLaw);
    const double error = std::abs(pad.VerticalForce(d, kZeta) - q) / q;
    EXPECT_LT(error, previous_error) << rings << " rings";
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-4);
}

TEST(FootpadSphericalCap, SmallDepthMatchesParaboloidClosedForm) {
  // For d << R the cap is a paraboloid u = x^2 / (2R) with alpha ~ 1: F ~ zeta pi R d^2.
  const double R = 0.2;
  const AxisymmetricIntrusion pad(MakeSphericalCapProfile(0.05, 0.016, R, 2000), kLaw);
  const double d = 1e-4;
  EXPECT_NEAR(pad.VerticalForce(d, kZeta), kZeta * std::numbers::pi * R * d * d, 2e-3 * kZeta * std::numbers::pi * R * d * d);
}

TEST(FootpadCone, ForceGrowsWithCubeOfDepth) {
  const AxisymmetricIntrusion pad(MakeConeProfile(0.05, 0.05, 1.2), kLaw);
  const double f1 = pad.VerticalForce(0.002, kZeta), f2 = pad.VerticalForce(0.004, kZeta);
  EXPECT_NEAR(f2 / f1, 8.0, 1e-9);
}

TEST(FootpadArea, SubmergedAreaOfFlatPad) {
  const double r = 0.05;
  const AxisymmetricIntrusion pad(MakeFlatProfile(r, 0.016), kLaw);
  EXPECT_NEAR(pad.SubmergedArea(0.005), std::numbers::pi * r * r + 2 * std::numbers::pi * r * 0.005, 1e-12);
  EXPECT_NEAR(pad.SubmergedArea(1e-12), std::numbers::pi * r * r, 1e-9);  // the bottom just under the surface
  EXPECT_EQ(pad.SubmergedArea(0.0), 0.0);
}

TEST(FootpadProfile, BadProfilesAreRefused) {
  EXPECT_THROW(MakeFlatProfile(0.0, 0.016), InputError);      // zero area
  EXPECT_THROW(MakeFlatProfile(-0.05, 0.016), InputError);
  EXPECT_THROW(MakeFlatProfile(NAN, 0.016), InputError);
  EXPECT_THROW(MakeChamferProfile(0.05, 0.016, 0.06), InputError);
  EXPECT_THROW(MakeExponentialProfile(0.05, 0.016, 0.01, 100.0, 10), InputError);  // rises above h
  EXPECT_THROW(MakeTabulatedProfile({{0.0, 0.0}, {0.02, 0.003}, {0.01, 0.004}}, 0.016), InputError);
  EXPECT_THROW(MakeTabulatedProfile({{0.0, 0.001}, {0.02, 0.003}}, 0.016), InputError);
  EXPECT_NO_THROW(MakeTabulatedProfile({{0.0, 0.0}, {0.02, 0.001}, {0.05, 0.01}}, 0.016));
}

}  // namespace
}  // namespace touchdown::geom
