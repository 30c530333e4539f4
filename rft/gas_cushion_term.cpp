#include "rft/gas_cushion_term.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "rft/rate_damping_term.h"

namespace touchdown::rft {

GasCushionLaw::GasCushionLaw(std::unique_ptr<StressLaw3D> inner, double chi, double c_g_N_s_m3)
    : ForwardingLaw3D(std::move(inner), "gas_cushion"), chi_(chi), c_g_(c_g_N_s_m3) {
  if (!(std::isfinite(chi_) && chi_ >= 0.0 && chi_ < 1.0))
    throw std::invalid_argument("GasCushionLaw: chi must be in [0, 1)");
  if (!(std::isfinite(c_g_) && c_g_ >= 0.0)) throw std::invalid_argument("GasCushionLaw: c_g must be finite and >= 0");
}

Eigen::Vector3d GasCushionLaw::DynamicStress(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  return inner_->DynamicStress(n, v) + NormalDampingStress(c_g_, n, v);
}

}  // namespace touchdown::rft
