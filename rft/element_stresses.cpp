#include "rft/element_stresses.h"

namespace touchdown::rft {

void ElementStresses::Resize(int n) {
  if (normal_Pa.size() == n) return;
  force_W.resize(3, n);
  normal_Pa.resize(n);
  shear_Pa.resize(n);
  depth_m.resize(n);
  leading.resize(n);
  if (one.size() != 1) one.Resize(1);
}

void ComputeElementStresses(const SurfaceElements& elements, const PadKinematics& k, const GroundSurface& ground,
                            const StressLaw3D& law, const DepthLaw& depth, ElementStresses* out) {
  out->Resize(elements.size());
  PadLevelTerms terms;
  terms.depth = depth;
  SurfaceElements& one = out->one;
  for (int i = 0; i < elements.size(); ++i) {
    one.p0_B.col(0) = elements.p0_B.col(i);
    one.p1_B.col(0) = elements.p1_B.col(i);
    one.p2_B.col(0) = elements.p2_B.col(i);
    one.n_B.col(0) = elements.n_B.col(i);
    one.area_m2[0] = elements.area_m2[i];
    const ContactWrench w = ComputeContactWrench(one, k, ground, law, terms);
    const Eigen::Vector3d n_W = k.R_WB * elements.n_B.col(i);
    const double area = elements.area_m2[i];
    const double f_n = w.force_W.dot(n_W);
    out->force_W.col(i) = w.force_W;
    out->normal_Pa[i] = area > 0.0 ? -f_n / area : 0.0;
    out->shear_Pa[i] = area > 0.0 ? (w.force_W - f_n * n_W).norm() / area : 0.0;
    const Eigen::Vector3d centroid_B = (elements.p0_B.col(i) + elements.p1_B.col(i) + elements.p2_B.col(i)) / 3.0;
    out->depth_m[i] = ground.Depth(k.p_WB + k.R_WB * centroid_B);
    out->leading[i] = w.leading_elements > 0 ? 1 : 0;
  }
}

}  // namespace touchdown::rft
