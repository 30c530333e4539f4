#pragma once
// Rate damping (the effect term `rate_damping`, rft/effect_terms.h) as a decorator around any
// StressLaw3D: on a leading element (n . v > 0) the soil adds a stress linear in the normal
// speed and independent of depth,
//
//   sigma_damp = -c (v . n) n      [Pa = N s/m^3 * m/s]
//
// pushing against the element's outward normal n (into the pad); c [N s/m^3] >= 0. Like the
// dynamic term (rft/dynamic_term.h) it is a DynamicStress: ComputeContactWrench integrates it over
// the submerged area, not over depth. A horizontal plate of area A moving down at speed v gets
// exactly c v A more upward force. Elements moving parallel to their face (the side wall of a pad
// moving straight down) or trailing get nothing. The wrapped law's stresses are kept unchanged.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

#include "rft/forwarding_law_3d.h"

namespace touchdown::rft {

class RateDampingLaw final : public ForwardingLaw3D {
 public:
  // Throws std::invalid_argument on a null law or a negative or non-finite c.
  RateDampingLaw(std::unique_ptr<StressLaw3D> inner, double c_N_s_m3);  // name e.g. "li2013+rate_damping"
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  bool has_dynamic_stress() const override { return true; }
  double c_N_s_m3() const { return c_; }

 private:
  double c_;
};

// -c (v.n) n on a leading element, 0 otherwise: the damping stress both RateDampingLaw and
// GasCushionLaw add.
inline Eigen::Vector3d NormalDampingStress(double c_N_s_m3, const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) {
  const double vn = n_W.dot(v_W);
  if (!(vn > 0.0) || c_N_s_m3 == 0.0) return Eigen::Vector3d::Zero();
  return (-c_N_s_m3 * vn) * n_W;
}

}  // namespace touchdown::rft
