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

#include "rft/stress_law_3d.h"

namespace touchdown::rft {

class DynamicTermLaw final : public StressLaw3D {
 public:
  DynamicTermLaw(std::unique_ptr<StressLaw3D> quasi_static, double lambda, double rho_c_kg_m3);
  std::string_view name() const override { return name_; }  // e.g. "li2013+dynamic"
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return quasi_static_->StressPerDepth(n_W, v_W);
  }
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  // The pad-level terms (depth law, compaction transient, added mass) are the wrapped law's.
  DepthLaw depth_law() const override { return quasi_static_->depth_law(); }
  Eigen::Vector3d CompactionStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return quasi_static_->CompactionStress(n_W, v_W);
  }
  double compaction_decay_depth_m() const override { return quasi_static_->compaction_decay_depth_m(); }
  bool has_compaction() const override { return quasi_static_->has_compaction(); }
  double added_mass_density_kg_m3() const override { return quasi_static_->added_mass_density_kg_m3(); }
  const StressLaw3D& quasi_static() const { return *quasi_static_; }
  double lambda() const { return lambda_; }
  double rho_c_kg_m3() const { return rho_c_; }

 private:
  std::unique_ptr<StressLaw3D> quasi_static_;
  double lambda_;
  double rho_c_;
  std::string name_;
};

}  // namespace touchdown::rft
