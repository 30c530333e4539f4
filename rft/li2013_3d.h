#pragma once
// Li, Zhang & Goldman's 2D law (Science 2013) extended to 3D by the decomposition of Treers,
// Cao & Stuart (RA-L 2021), as a StressLaw3D.
//
// For an element with outward unit normal n and velocity v (z up): e2 is the horizontal
// direction of n, e1 = e2 x z. The velocity splits into v1 (along e1) and v23 (in the e2-z
// plane). The 2D law acts in the e2-z plane (attack angle beta of n in that plane, intrusion
// angle gamma of v23) and a lateral term alpha_y acts along e1, each weighted by a function of
// the speed fractions s1 = |v1|/|v|, s23 = |v23|/|v|:
//
//   stress / depth = zeta ( f23(s23) (-alpha_x e2 + alpha_z z) - f1(s1) alpha_y sign(v.e1) e1 )
//
// Choices made here (each documented in li2013_3d.cpp):
//  - Li's nine coefficients, not the placeholder alphas of the Treers MATLAB release.
//  - f1 and f23 are normalised to 1 at s = 1, so motion in the e2-z plane is exactly Li's 2D
//    law and vertical intrusion of an axisymmetric pad is exactly the profile integral.
//  - Facets within 1 degree of horizontal blend towards e2 = horizontal direction of v (Li's
//    2D experiment for a flat plate); exactly horizontal facets never give NaN.
//  - alpha_y = 0.2035: the constant term of Treers et al.'s fit (their release adds a small
//    linear term in beta, -0.0015 per degree, with a unit slip; it is left out), assumed to be in
//    the same zeta-normalised units as Li's alphas.
#include <Eigen/Core>
#include <string_view>

#include "rft/li2013.h"
#include "rft/stress_law_3d.h"

namespace touchdown::rft {

// Treers et al.'s lateral coefficient alpha_y (constant term of their fit).
inline constexpr double kTreersAlphaY = 0.2035;

// Li's fit evaluated from the sines and cosines of beta and gamma (no trigonometric calls);
// equal to Li2013Alpha(beta, gamma) for any angles, mirror rule included (cos gamma < 0).
Alpha2 Li2013AlphaFromSinCos(const Li2013Coefficients& c, double sin_beta, double cos_beta, double sin_gamma,
                             double cos_gamma);

// Treers et al.'s speed-fraction weights, normalised so that f(0) = 0 and f(1) = 1, in closed
// form (one tanh / atanh each).
double TreersLateralWeight(double s1);   // f1
double TreersInPlaneWeight(double s23);  // f23
// The same weights from a cubic Hermite table (values and exact slopes at 1025 nodes on [0, 1]):
// f1 within 1e-11 and f23 within 5e-8 of the closed forms (tested; f23's error sits near s = 0),
// and cheaper than their expm1 / log1p, a fifth of the force loop of a rotating pad. The law uses
// these.
double TreersLateralWeightTabulated(double s1);
double TreersInPlaneWeightTabulated(double s23);

class Li2013TreersLaw final : public StressLaw3D {
 public:
  explicit Li2013TreersLaw(double zeta_N_m3, Li2013Coefficients coefficients = {},
                           double alpha_y = kTreersAlphaY);
  std::string_view name() const override { return "li2013"; }
  LawKind kind() const override { return LawKind::kLi2013; }
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  // The common case (a facet more than 1 degree from horizontal, a velocity with a part in its
  // e2-z plane) in branch-free passes over the batch; the others element by element.
  void StressPerDepthBatch(StressBatch& batch) const override;
  double zeta_N_m3() const { return zeta_; }

 private:
  // The decomposition with a given horizontal unit e2 = (e2x, e2y, 0), for a normal with attack
  // angle beta in the e2-z plane (sin, cos) and a velocity v != 0.
  Eigen::Vector3d Decomposed(double sin_beta, double cos_beta, const Eigen::Vector3d& v, double e2x,
                             double e2y) const;
  double zeta_;
  Li2013Coefficients c_;
  double alpha_y_;
};

}  // namespace touchdown::rft
