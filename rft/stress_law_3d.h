#pragma once
// A 3D stress law: the stress on a leading surface element per unit depth, as a vector in W
// (z up), for the element's outward unit normal n and its velocity v. Implementations carry
// their soil scaling (zeta for Li 2013 via Treers et al. 2021; xi_n and mu_surf for Agarwal et
// al. 2023), so the result is in N/m^2 per m of depth. A speed-dependent (dynamic) term adds a
// stress not proportional to depth; see DynamicStress.
#include <Eigen/Core>
#include <string_view>

namespace touchdown::rft {

class StressLaw3D {
 public:
  virtual ~StressLaw3D() = default;
  virtual std::string_view name() const = 0;
  // Stress per unit depth [N/m^3] on a leading element (n . v >= 0). |v| > 0.
  virtual Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const = 0;
  // Depth-independent stress [N/m^2] (dynamic RFT: lambda rho (v.n)^2 against n), 0 by default.
  virtual Eigen::Vector3d DynamicStress(const Eigen::Vector3d& /*n_W*/, const Eigen::Vector3d& /*v_W*/) const {
    return Eigen::Vector3d::Zero();
  }
};

}  // namespace touchdown::rft
