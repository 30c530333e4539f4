#include "rft/pad_effect_terms.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace touchdown::rft {

DepthExponentLaw::DepthExponentLaw(std::unique_ptr<StressLaw3D> inner, double exponent, double reference_m)
    : ForwardingLaw3D(std::move(inner), "depth_exponent"), law_{exponent, reference_m} {
  if (!(std::isfinite(exponent) && exponent > 0.0 && std::isfinite(reference_m) && reference_m > 0.0))
    throw std::invalid_argument("DepthExponentLaw: p and z_ref must be finite and > 0");
}

CompactionPeakLaw::CompactionPeakLaw(std::unique_ptr<StressLaw3D> inner, double k_c_kg_m3, double d_c_m)
    : ForwardingLaw3D(std::move(inner), "compaction_peak"), k_c_(k_c_kg_m3), d_c_(d_c_m) {
  if (!(std::isfinite(k_c_) && k_c_ >= 0.0 && std::isfinite(d_c_) && d_c_ > 0.0))
    throw std::invalid_argument("CompactionPeakLaw: k_c must be finite and >= 0, d_c finite and > 0");
  if (inner_->has_compaction()) throw std::invalid_argument("CompactionPeakLaw: the wrapped law already has one");
}

Eigen::Vector3d CompactionPeakLaw::CompactionStress(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  const double vn = n.dot(v);
  if (!(vn > 0.0)) return Eigen::Vector3d::Zero();  // trailing or sliding elements compact nothing
  return (-k_c_ * vn * vn) * n;
}

AddedMassLaw::AddedMassLaw(std::unique_ptr<StressLaw3D> inner, double density_kg_m3)
    : ForwardingLaw3D(std::move(inner), "added_mass"), density_(density_kg_m3) {
  if (!(std::isfinite(density_) && density_ >= 0.0))
    throw std::invalid_argument("AddedMassLaw: c_a rho must be finite and >= 0");
}

}  // namespace touchdown::rft
