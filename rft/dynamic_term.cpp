#include "rft/dynamic_term.h"

#include <utility>

namespace touchdown::rft {

DynamicTermLaw::DynamicTermLaw(std::unique_ptr<StressLaw3D> quasi_static, double lambda, double rho_c_kg_m3)
    : ForwardingLaw3D(std::move(quasi_static), "dynamic"), lambda_(lambda), rho_c_(rho_c_kg_m3) {}

Eigen::Vector3d DynamicTermLaw::DynamicStress(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  const double vn = n.dot(v);
  if (!(vn > 0.0)) return Eigen::Vector3d::Zero();  // trailing or sliding elements: no impact
  return (-lambda_ * rho_c_ * vn * vn) * n;
}

}  // namespace touchdown::rft
