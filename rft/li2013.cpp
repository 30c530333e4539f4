#include "rft/li2013.h"

#include <cmath>
#include <numbers>

namespace touchdown::rft {

namespace {
constexpr double kPi = std::numbers::pi;

// Reduce to (-pi, pi].
double WrapAngle(double a) {
  a = std::remainder(a, 2.0 * kPi);  // in [-pi, pi]
  return a <= -kPi ? a + 2.0 * kPi : a;
}
}  // namespace

Alpha2 Li2013FitRaw(const Li2013Coefficients& c, double b, double g) {
  Alpha2 a;
  a.z = c.A00 + c.A10 * std::cos(2 * b) + c.B11 * std::sin(2 * b + g) + c.B01 * std::sin(g) +
        c.Bm11 * std::sin(-2 * b + g);
  a.x = c.C11 * std::cos(2 * b + g) + c.C01 * std::cos(g) + c.Cm11 * std::cos(-2 * b + g) +
        c.D10 * std::sin(2 * b);
  return a;
}

Alpha2 Li2013Alpha(const Li2013Coefficients& c, double beta_rad, double gamma_rad) {
  const double g = WrapAngle(gamma_rad);
  // Motion with a backward horizontal component is the mirror image (x -> -x) of
  // motion with a forward one: the plate's tilt and the horizontal stress flip sign.
  if (g > kPi / 2 || g < -kPi / 2) {
    const double g_mirror = g > 0 ? kPi - g : -kPi - g;
    Alpha2 a = Li2013FitRaw(c, -beta_rad, g_mirror);
    a.x = -a.x;
    return a;
  }
  return Li2013FitRaw(c, beta_rad, g);
}

}  // namespace touchdown::rft
