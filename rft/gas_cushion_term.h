#pragma once
// The gas cushion (the effect library's `gas_cushion`, drop_tests/effects.h) as a decorator
// around any StressLaw3D, for a bed in air: gas trapped in the pores carries part of the load, so
// the quasi-static stress per depth is scaled by (1 - chi), and the gas forced out of the pores
// damps the motion with a stress linear in the normal speed on leading elements (n . v > 0):
//
//   stress per depth  -> (1 - chi) * wrapped law's        chi [-] in [0, 1)
//   sigma_gas = -c_g (v . n) n   (a DynamicStress)       c_g [N s/m^3] >= 0
//
// The wrapped law's own DynamicStress (e.g. the inertial term) is kept unscaled, as in the rig's
// form (effects.h: zeta -> (1 - chi) zeta, F += c_g v I2). The decorator knows nothing about the
// atmosphere: whoever builds the law applies it only to beds in air.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

#include "rft/stress_law_3d.h"

namespace touchdown::rft {

class GasCushionLaw final : public StressLaw3D {
 public:
  // Throws std::invalid_argument on a null law, chi outside [0, 1) or a negative c_g.
  GasCushionLaw(std::unique_ptr<StressLaw3D> inner, double chi, double c_g_N_s_m3);
  std::string_view name() const override { return name_; }  // e.g. "li2013+gas_cushion"
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return (1.0 - chi_) * inner_->StressPerDepth(n_W, v_W);
  }
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  // The pad-level terms (depth law, compaction transient, added mass) are the wrapped law's.
  DepthLaw depth_law() const override { return inner_->depth_law(); }
  Eigen::Vector3d CompactionStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return inner_->CompactionStress(n_W, v_W);
  }
  double compaction_decay_depth_m() const override { return inner_->compaction_decay_depth_m(); }
  bool has_compaction() const override { return inner_->has_compaction(); }
  double added_mass_density_kg_m3() const override { return inner_->added_mass_density_kg_m3(); }
  const StressLaw3D& inner() const { return *inner_; }
  double chi() const { return chi_; }
  double c_g_N_s_m3() const { return c_g_; }

 private:
  std::unique_ptr<StressLaw3D> inner_;
  double chi_;
  double c_g_;
  std::string name_;
};

}  // namespace touchdown::rft
