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
  double radius_m() const { return radius_m_; }
  double thickness_m() const { return thickness_m_; }

 private:
  struct Piece {
    double x0, u0, dx, du, length, alpha_z;
  };
  std::vector<Piece> pieces_;
  std::vector<double> top_u_;     // u at the upper end of each piece (never decreasing)
  std::vector<double> slope_sum_;  // prefix sums over whole pieces: F/zeta = slope * d + offset
  std::vector<double> offset_sum_;
  double radius_m_;
  double thickness_m_;
};

}  // namespace touchdown::geom
