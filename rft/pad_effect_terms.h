#pragma once
// The effect library's pad-level terms (drop_tests/model/effects.h) as decorators around any
// StressLaw3D. Each keeps the wrapped law's stresses and sets one constant parameter that the
// contact (rft/contact_wrench.h) or the rigid-body dynamics read (rft/stress_law_3d.h):
//
//   DepthExponentLaw  depth_exponent   stress sigma z_ref (z / z_ref)^p instead of sigma z; the
//                                      contact integrates z^p exactly over each clipped triangle
//   CompactionPeakLaw compaction_peak  stress -k_c (v.n)^2 n on leading elements (n . v > 0),
//                                      integrated over the submerged area and scaled by
//                                      exp(-z_pad / d_c), z_pad the pad's penetration
//   AddedMassLaw      added_mass       c_a rho of the entrained cone (rft/entrained_mass.h); the
//                                      free drop and the lander add its inertia to the pad
//
// For a level axisymmetric pad moving straight down each reduces to the rig's form
// (drop_tests/model/effects.h EffectSoilResponse): the compaction stress gives k_c v^2 exp(-d/d_c) I_3(d)
// as the dynamic term gives lambda rho v^2 I_3(d).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

#include "rft/forwarding_law_3d.h"

namespace touchdown::rft {

class DepthExponentLaw final : public ForwardingLaw3D {
 public:
  // Throws std::invalid_argument unless p > 0 and z_ref > 0 are finite.
  DepthExponentLaw(std::unique_ptr<StressLaw3D> inner, double exponent, double reference_m);
  DepthLaw depth_law() const override { return law_; }

 private:
  DepthLaw law_;
};

class CompactionPeakLaw final : public ForwardingLaw3D {
 public:
  // Throws std::invalid_argument unless k_c >= 0 and d_c > 0 are finite, or if the wrapped law
  // already has a compaction term (one decay depth per law).
  CompactionPeakLaw(std::unique_ptr<StressLaw3D> inner, double k_c_kg_m3, double d_c_m);
  Eigen::Vector3d CompactionStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  double compaction_decay_depth_m() const override { return d_c_; }
  bool has_compaction() const override { return true; }
  double k_c_kg_m3() const { return k_c_; }

 private:
  double k_c_;
  double d_c_;
};

class AddedMassLaw final : public ForwardingLaw3D {
 public:
  // density = c_a rho [kg/m^3]; throws std::invalid_argument unless finite and >= 0.
  AddedMassLaw(std::unique_ptr<StressLaw3D> inner, double density_kg_m3);
  double added_mass_density_kg_m3() const override { return density_; }

 private:
  double density_;
};

}  // namespace touchdown::rft
