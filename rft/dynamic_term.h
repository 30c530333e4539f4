#pragma once
// The dynamic (inertial) term of dynamic RFT (Agarwal, Karsai, Goldman & Kamrin, Sci. Adv. 2021)
// as a decorator around any quasi-static StressLaw3D.
//
// On a leading element (n . v > 0) the soil adds a stress that does not scale with depth:
//
//   sigma_dyn = -lambda rho_c (v . n)^2 n      [Pa = kg/m^3 * (m/s)^2]
//
// pushing against the element's outward normal n (into the pad). lambda [-] is the
// dimensionless inertial coefficient, rho_c [kg/m^3] the medium's (critical-state) bulk
// density. ComputeContactWrench integrates it over the submerged area, not over depth.
// The quasi-static stress per depth is the wrapped law's, unchanged.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

#include "rft/forwarding_law_3d.h"

namespace touchdown::rft {

class DynamicTermLaw final : public ForwardingLaw3D {
 public:
  // Throws std::invalid_argument on a null law.
  DynamicTermLaw(std::unique_ptr<StressLaw3D> quasi_static, double lambda, double rho_c_kg_m3);  // "li2013+dynamic"
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  // DynamicStress replaces the inner law's, so none of the inner's depth-independent shear is left.
  Eigen::Vector3d MobilisedShearStress(const Eigen::Vector3d&, const Eigen::Vector3d&) const override {
    return Eigen::Vector3d::Zero();
  }
  bool has_dynamic_stress() const override { return true; }
  const StressLaw3D& quasi_static() const { return inner(); }
  double lambda() const { return lambda_; }
  double rho_c_kg_m3() const { return rho_c_; }

 private:
  double lambda_;
  double rho_c_;
};

}  // namespace touchdown::rft
