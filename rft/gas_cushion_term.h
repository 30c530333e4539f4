#pragma once
// The gas cushion (the effect term `gas_cushion`, rft/effect_terms.h) as a decorator around any
// StressLaw3D, for a bed in air: gas trapped in the pores carries part of the load, so
// the quasi-static stress per depth is scaled by (1 - chi), and the gas forced out of the pores
// damps the motion with a stress linear in the normal speed on leading elements (n . v > 0):
//
//   stress per depth  -> (1 - chi) * wrapped law's        chi [-] in [0, 1)
//   sigma_gas = -c_g (v . n) n   (a DynamicStress)       c_g [N s/m^3] >= 0
//
// The wrapped law's own DynamicStress (e.g. the inertial term) is kept unscaled, as in the
// axisymmetric form (zeta -> (1 - chi) zeta, F += c_g v I2; docs/physics.md section 4). The decorator knows nothing about the
// atmosphere: whoever builds the law applies it only to beds in air.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

#include "rft/forwarding_law_3d.h"

namespace touchdown::rft {

class GasCushionLaw final : public ForwardingLaw3D {
 public:
  // Throws std::invalid_argument on a null law, chi outside [0, 1) or a negative c_g.
  GasCushionLaw(std::unique_ptr<StressLaw3D> inner, double chi, double c_g_N_s_m3);  // "li2013+gas_cushion"
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return (1.0 - chi_) * inner_->StressPerDepth(n_W, v_W);
  }
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  bool has_dynamic_stress() const override { return true; }
  Eigen::Vector3d MobilisedShearPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return (1.0 - chi_) * inner_->MobilisedShearPerDepth(n_W, v_W);  // scaled as StressPerDepth
  }
  void StressPerDepthBatch(StressBatch& batch) const override {
    inner_->StressPerDepthBatch(batch);
    for (int i = 0; i < batch.count; ++i) {
      batch.sx[i] *= 1.0 - chi_;
      batch.sy[i] *= 1.0 - chi_;
      batch.sz[i] *= 1.0 - chi_;
    }
  }
  double chi() const { return chi_; }
  double c_g_N_s_m3() const { return c_g_; }

 private:
  double chi_;
  double c_g_;
};

}  // namespace touchdown::rft
