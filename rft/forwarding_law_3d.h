#pragma once
// The base of the effect decorators (rft/dynamic_term.h, rate_damping_term.h, gas_cushion_term.h):
// a StressLaw3D that wraps another and forwards every term to it, so each decorator overrides
// only the term it adds and the others pass through however the decorators are stacked.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

#include "rft/stress_law_3d.h"

namespace touchdown::rft {

class ForwardingLaw3D : public StressLaw3D {
 public:
  // Throws std::invalid_argument on a null law.
  ForwardingLaw3D(std::unique_ptr<StressLaw3D> inner, std::string_view suffix);
  std::string_view name() const override { return name_; }
  LawKind kind() const override { return inner_->kind(); }
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return inner_->StressPerDepth(n_W, v_W);
  }
  void StressPerDepthBatch(StressBatch& batch) const override { inner_->StressPerDepthBatch(batch); }
  bool has_dynamic_stress() const override { return inner_->has_dynamic_stress(); }
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return inner_->DynamicStress(n_W, v_W);
  }
  bool has_mobilised_shear() const override { return inner_->has_mobilised_shear(); }
  Eigen::Vector3d MobilisedShearPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return inner_->MobilisedShearPerDepth(n_W, v_W);
  }
  Eigen::Vector3d MobilisedShearStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override {
    return inner_->MobilisedShearStress(n_W, v_W);
  }
  const StressLaw3D& inner() const { return *inner_; }

 protected:
  std::unique_ptr<StressLaw3D> inner_;

 private:
  std::string name_;
};

}  // namespace touchdown::rft
