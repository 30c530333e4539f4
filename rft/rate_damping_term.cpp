#include "rft/rate_damping_term.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace touchdown::rft {

RateDampingLaw::RateDampingLaw(std::unique_ptr<StressLaw3D> inner, double c_N_s_m3)
    : ForwardingLaw3D(std::move(inner), "rate_damping"), c_(c_N_s_m3) {
  if (!(std::isfinite(c_) && c_ >= 0.0)) throw std::invalid_argument("RateDampingLaw: c must be finite and >= 0");
}

Eigen::Vector3d RateDampingLaw::DynamicStress(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  return inner_->DynamicStress(n, v) + NormalDampingStress(c_, n, v);
}

}  // namespace touchdown::rft
