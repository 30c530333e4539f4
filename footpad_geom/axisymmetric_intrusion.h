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
  // On a polyline with corners only (flat, chamfer, cone, table) it is exact: the chords'
  // quadratics in d. A sampled smooth curve (ProfilePoint::smooth: the exponential and
  // spherical-cap bottoms) is different: there the chords' slopes dI_k/dd = 2 pi x cos^k(beta) /
  // sin(beta) jump at every joint while the curve's do not, and a speed term rides on I_k through
  // the whole stroke, so hundreds of kinks would cut the integrator's step at each (8 times the
  // steps of the quasi-static drop). Next to a smooth joint a piece takes instead the Hermite
  // cubic through the polyline's values with the mean of the chords' slopes at the joints, less
  // its mean excess over the chord (a bias linear across the piece): I_k is then C1 through the
  // curve as the real pad's is, and keeps the polyline's mean over every piece, so drops agree
  // with the polyline's to their integration tolerance (tests/lander/pad/rig_drop_steps_test.cpp).
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
  // A piece next to a smooth joint (CosinePowerIntegral): the corrections to dI_k/dT [m^2] at its
  // lower and upper end that give the joints' slopes, and the bias [m^2] taken off at either end.
  struct Blend {
    bool active = false;
    double lo = 0.0, hi = 0.0, bias_lo = 0.0, bias_hi = 0.0;
  };
  std::vector<Blend> blend_[4];  // per piece
  void SmoothJoints(const AxisymmetricProfile& profile, int k);
  double radius_m_;
  double thickness_m_;
};

}  // namespace touchdown::geom
