#pragma once
// The generic 2D resistive-force stress law of Li, Zhang & Goldman (Science 2013).
//
// A surface element at attack angle beta (tilt from horizontal) moving at intrusion angle
// gamma (velocity direction from horizontal, positive moving down) feels, per unit area
// and per unit depth, the stresses zeta * alpha_z and zeta * alpha_x. The alphas are the
// dimensionless generic fit (its values equal the N/cm^3 stresses of a medium whose
// zeta is 1 N/cm^3; alpha_z(0, pi/2) = 1 exactly).
#include <string_view>

namespace touchdown::rft {

// The nine Fourier coefficients of the generic fit (Li et al. 2013, Fig. 4 / eq. S5).
struct Li2013Coefficients {
  double A00 = 0.206, A10 = 0.169, B11 = 0.212, B01 = 0.358, Bm11 = 0.055;
  double C11 = -0.124, C01 = 0.253, Cm11 = 0.007, D10 = 0.088;
};

// Dimensionless stress coefficients of one element: z is vertical (positive = up, i.e.
// resisting downward motion), x is horizontal (positive along +x).
struct Alpha2 {
  double z = 0.0;
  double x = 0.0;
};

// The fit itself, valid for beta and gamma in [-pi/2, pi/2]. No range handling.
Alpha2 Li2013FitRaw(const Li2013Coefficients& c, double beta_rad, double gamma_rad);

// The law for any beta and gamma. The fit is pi-periodic in beta (a plate is the same plate
// after a half turn), so beta needs no reduction; gamma is wrapped to (-pi, pi] and |gamma| > pi/2 uses the mirror rule
// alpha_z(-beta, pi - gamma) = alpha_z(beta, gamma), alpha_x(-beta, pi - gamma) = -alpha_x(beta, gamma).
Alpha2 Li2013Alpha(const Li2013Coefficients& c, double beta_rad, double gamma_rad);

inline Alpha2 Li2013Alpha(double beta_rad, double gamma_rad) {
  return Li2013Alpha(Li2013Coefficients{}, beta_rad, gamma_rad);
}

}  // namespace touchdown::rft
