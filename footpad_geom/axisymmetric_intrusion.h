#pragma once
// Vertical intrusion of an axisymmetric pad (paper 002, eqs. 3-4, along arc length):
//
//   F_z(d) = zeta * sum over the submerged profile of alpha_z(beta(s), pi/2) (d - u(s)) 2 pi x(s) ds
//
// with d the depth of the pad's lowest point. Every piece of the profile, the side wall
// included, leads a straight-down motion (its outward normal has no upward component); the
// wall's normal is perpendicular to the motion and is kept, as in the paper's integral.
// For d > h the profile lies between depths d - h and d, which is the paper's d > h rule; the
// top face trails and carries nothing. On each straight piece the integrand is a polynomial
// in arc length, so the integral is exact for the polyline; F_z(d) is then a cubic in d
// between consecutive profile heights. Pieces wholly below the surface add a term linear in
// d, kept as prefix sums, so one evaluation costs a binary search plus one partial piece.
#include <vector>

#include "footpad_geom/axisymmetric_profile.h"
#include "rft/stress_law.h"

namespace touchdown::geom {

class AxisymmetricIntrusion {
 public:
  AxisymmetricIntrusion(const AxisymmetricProfile& profile, const rft::StressLaw2D& law);

  // Soil reaction on the pad, upward [N], for a lowest-point depth d [m] and zeta [N/m^3].
  double VerticalForce(double depth_m, double zeta_N_m3) const;
  // Area of the pad surface below the free surface [m^2].
  double SubmergedArea(double depth_m) const;

  // Additions for speed-dependent effect terms (drop_tests/model/effects.h). For straight-down motion
  // an element of attack angle beta has v.n = v cos(beta) (n the outward normal, v down).
  // Integral of cos^k(beta) dA over the submerged leading surface [m^2], k = 0..3; k = 0 is
  // SubmergedArea, k = 2 weights a normal stress c (v.n), k = 3 the vertical part of lambda (v.n)^2.
  // Exact for the polyline at every profile point. Between two points it is the chord's quadratic,
  // except next to a smooth point (ProfilePoint::smooth) of a sampled curve: there the chords'
  // slopes dI_k/dd differ (cos^k(beta)/sin(beta) jumps from chord to chord) while the curve's do
  // not, so the piece takes the cubic with the joint's mean slope instead. The sampled curve's
  // I_k is then smooth in d as the real pad's is: a speed term rides on it through the whole
  // stroke, and a kink at every one of hundreds of joints would make the integrator restart its
  // order at each. The two differ by O(segment^2), as the polyline differs from the curve.
  double CosinePowerIntegral(double depth_m, int k) const;
  // Radius of the submerged footprint [m]: the radius at which the profile crosses the free
  // surface (the rim once the bottom is under). 0 at d <= 0; a flat pad jumps to r at d = 0+.
  double FootprintRadius(double depth_m) const;
  // d(FootprintRadius)/d(depth) [-]: dx/du of the piece cut by the surface; 0 on the side wall
  // and on a flat bottom (where the footprint is already whole).
  double FootprintRadiusSlope(double depth_m) const;
  // Vertical force for the depth power law sigma = zeta alpha z_ref (z / z_ref)^p [N]: exact on
  // every straight piece (the integrand z^p times a radius linear in z integrates in closed
  // form). p = 1 gives VerticalForce. Costs one or two pow() per submerged piece.
  double PowerLawVerticalForce(double depth_m, double zeta_N_m3, double exponent, double z_ref_m) const;
  double radius_m() const { return radius_m_; }
  double thickness_m() const { return thickness_m_; }

 private:
  struct Piece {
    double x0, u0, dx, du, length, alpha_z;
    double cos_beta;  // dx / length
  };
  std::vector<Piece> pieces_;
  std::vector<double> top_u_;     // u at the upper end of each piece (never decreasing)
  std::vector<double> slope_sum_;  // prefix sums over whole pieces: F/zeta = slope * d + offset
  std::vector<double> offset_sum_;
  std::vector<double> cos_sum_[4];  // prefix sums over whole pieces of cos^k(beta) times their area
  // Per piece, the Hermite corrections to dI_k/dT at its lower and upper end (0 at corners).
  std::vector<double> blend_lo_[4];
  std::vector<double> blend_hi_[4];
  std::vector<double> bias_[4];  // per profile point
  void SmoothJoints(const AxisymmetricProfile& profile, int k);
  double radius_m_;
  double thickness_m_;
};

}  // namespace touchdown::geom
