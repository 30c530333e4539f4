#pragma once
// The soil stress on each surface element of a pad, for outputs (ParaView's per-element fields):
// what ComputeContactWrench (rft/contact_wrench.h) sums, element by element. Evaluated at output
// samples only, never in a right-hand side; into a caller's buffer that allocates only when the
// element count grows.
//
// Each element's force is ComputeContactWrench over that element alone, with the same law, pose,
// twist, ground and depth law, so it is exactly the element's share of the sum (up to the contact's
// reuse of one stress per class of equal normals, a 1e-12 relative difference, and its choice of the
// translating path for spins below 1e-9 of the speed). The pad-level compaction and added mass act on
// the pad as a whole (they depend on the pad's penetration and footprint) and are left out.
#include <Eigen/Core>

#include "rft/contact_wrench.h"

namespace touchdown::rft {

struct ElementStresses {
  Eigen::Matrix3Xd force_W;   // soil on the element [N]
  Eigen::VectorXd normal_Pa;  // -F.n / A: compression positive, n the outward normal, A the element's area
  Eigen::VectorXd shear_Pa;   // |F - (F.n) n| / A
  Eigen::VectorXd depth_m;    // depth of the element's centroid below the surface (negative above it)
  Eigen::VectorXi leading;    // 1 where the element is submerged and leads the motion, else 0
  // Scratch: one element at a time.
  SurfaceElements one;

  void Resize(int n);
};

// Fills `out` (resized to elements.size()) for the pad at `kinematics` on `ground` under `law` with
// the depth law `depth`.
void ComputeElementStresses(const SurfaceElements& elements, const PadKinematics& kinematics,
                            const GroundSurface& ground, const StressLaw3D& law, const DepthLaw& depth,
                            ElementStresses* out);

}  // namespace touchdown::rft
