#pragma once
// A 3D stress law: the stress on a leading surface element per unit depth, as a vector in W
// (z up), for the element's outward unit normal n and its velocity v. Implementations carry
// their soil scaling (zeta for Li 2013 via Treers et al. 2021; xi_n and mu_surf for Agarwal et
// al. 2023), so the result is in N/m^2 per m of depth. A speed-dependent (dynamic) term adds a
// stress not proportional to depth; see DynamicStress.
//
// Terms that act on the pad as a whole (a depth law other than linear, the bed's compaction
// transient, the entrained mass) are not a law's business: rft/pad_level_terms.h.
#include <Eigen/Core>
#include <string_view>

#include "rft/law_kind.h"

namespace touchdown::rft {

// Normals n_W, velocities v_W and the resulting stresses sigma of up to kCapacity elements, one
// array per component (structure of arrays, so a law's batch loop can be vectorised).
struct StressBatch {
  static constexpr int kCapacity = 64;
  int count = 0;
  alignas(64) double nx[kCapacity], ny[kCapacity], nz[kCapacity];
  alignas(64) double vx[kCapacity], vy[kCapacity], vz[kCapacity];
  alignas(64) double sx[kCapacity], sy[kCapacity], sz[kCapacity];
};

class StressLaw3D {
 public:
  virtual ~StressLaw3D() = default;
  // The name outputs give the law, decorators included ("li2013+rate_damping"); for people, not
  // for dispatch.
  virtual std::string_view name() const = 0;
  // Which of the soil laws this is (a decorator: the law it wraps), for code that treats a law by
  // its kind (Bekker's own depth law, say).
  virtual LawKind kind() const = 0;
  // Stress per unit depth [N/m^3] on a leading element (n . v >= 0). |v| > 0.
  virtual Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const = 0;
  // StressPerDepth for a batch of elements (StressBatch): the same values element by element. The
  // force loop of a rotating pad calls this, so the loop pays one virtual call per batch and a law
  // can work on many elements at once (Li2013TreersLaw does, in SIMD-friendly passes). A law that
  // overrides StressPerDepth of a law it wraps overrides this too.
  virtual void StressPerDepthBatch(StressBatch& batch) const {
    for (int i = 0; i < batch.count; ++i) {
      const Eigen::Vector3d s = StressPerDepth(Eigen::Vector3d(batch.nx[i], batch.ny[i], batch.nz[i]),
                                               Eigen::Vector3d(batch.vx[i], batch.vy[i], batch.vz[i]));
      batch.sx[i] = s.x();
      batch.sy[i] = s.y();
      batch.sz[i] = s.z();
    }
  }
  // Whether DynamicStress can be non-zero (the contact skips it otherwise). A law that overrides
  // DynamicStress returns true.
  virtual bool has_dynamic_stress() const { return false; }
  // Depth-independent stress [N/m^2] (dynamic RFT: lambda rho (v.n)^2 against n), 0 by default.
  virtual Eigen::Vector3d DynamicStress(const Eigen::Vector3d& /*n_W*/, const Eigen::Vector3d& /*v_W*/) const {
    return Eigen::Vector3d::Zero();
  }
  // Janosi-Hanamoto's shear (rft/bekker_law.h): the part of StressPerDepth (per unit depth) and of
  // DynamicStress (depth-independent) that grows with the pad's shear displacement j as
  // m = 1 - exp(-j / K). Both are included fully in the two stresses above; the contact takes
  // (1 - m) of them off again for a pad whose PadKinematics::shear_mobilisation m < 1. Laws without
  // such a shear return false and zero (the contact then never calls them). A decorator that scales
  // or replaces its inner law's stress does the same to these.
  virtual bool has_mobilised_shear() const { return false; }
  virtual Eigen::Vector3d MobilisedShearPerDepth(const Eigen::Vector3d& /*n_W*/, const Eigen::Vector3d& /*v_W*/) const {
    return Eigen::Vector3d::Zero();
  }
  virtual Eigen::Vector3d MobilisedShearStress(const Eigen::Vector3d& /*n_W*/, const Eigen::Vector3d& /*v_W*/) const {
    return Eigen::Vector3d::Zero();
  }
};

}  // namespace touchdown::rft
