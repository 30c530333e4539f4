#pragma once
// The 3D resistive force theory of Agarwal, Goldman & Kamrin (PNAS 2023) as a StressLaw3D.
//
// For an element whose plate has downward-facing unit normal m (the element's outward normal n
// or -n, whichever points down) moving in direction u = v/|v| (z up):
//
//   alpha_gen = f1 m + f2 u - f3 z,   f_k = sum_j c_k^j T_j(x1, x2, x3),
//   x1 = -u.z (= sin gamma),  x2 = -m.z (= cos beta),  x3 = m.u,
//
// T_j the 20 monomials of degree <= 3 in (x1, x2, x3). This is the paper's (r, theta, z) form
// written without the local frame (alpha_r = f1 sin b cos psi + f2 cos g, alpha_theta = f1 sin b
// sin psi, alpha_z = -f1 cos b - f2 sin g - f3), so it needs no special case for horizontal
// facets or vertical velocities. The tangential part of alpha (relative to the plate) is
// limited by surface friction: |alpha_t| <= mu_surf |alpha_n|. Then
//
//   stress / depth = xi_n alpha_gen / alpha_gen_z(horizontal plate, straight down),
//   xi_n = rho g (894 mu^3 - 386 mu^2 + 89 mu)   (AgarwalScalingXi, rft/soil.h).
//
// The division (0.87504 with the coefficients used) makes xi_n exactly the vertical stress per
// unit depth on a horizontal plate pushed straight down, i.e. the quantity zeta is for Li's law
// and that rft/soil.h and data/ already treat it as; pass normalise_to_plate = false for the raw
// fit. See agarwal2023.cpp for the coefficient table and the two disputed entries.
#include <Eigen/Core>
#include <array>
#include <string_view>

#include "rft/stress_law_3d.h"

namespace touchdown::rft {

struct Agarwal2023Coefficients {
  std::array<double, 20> c1, c2, c3;
};
// The table as used here (see the .cpp for the choice between public copies).
const Agarwal2023Coefficients& Agarwal2023Table();

class Agarwal2023Law final : public StressLaw3D {
 public:
  // xi_n [N/m^3]; mu_surf: intruder-surface friction coefficient [-].
  Agarwal2023Law(double xi_n_N_m3, double mu_surf, bool normalise_to_plate = true);
  std::string_view name() const override { return "agarwal2023"; }
  LawKind kind() const override { return LawKind::kAgarwal2023; }
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;

  // The raw generic coefficient vector alpha_gen (friction-limited, not normalised) for a
  // plate with downward-facing normal m and unit motion direction u.
  Eigen::Vector3d GenericAlpha(const Eigen::Vector3d& m, const Eigen::Vector3d& u) const;
  double plate_normaliser() const { return plate_normaliser_; }

 private:
  double xi_n_;
  double mu_surf_;
  double plate_normaliser_ = 1.0;  // alpha_gen_z(beta = 0, gamma = pi/2) when normalising
};

}  // namespace touchdown::rft
