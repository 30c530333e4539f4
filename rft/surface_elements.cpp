#include "rft/surface_elements.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace touchdown::rft {

void SurfaceElements::UpdateBounds() {
  const int n = size();
  block_min_B.resize(3, block_count());
  block_max_B.resize(3, block_count());
  double r2 = 0.0;
  for (int b = 0; b < block_count(); ++b) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (int e = b * kBlockSize; e < std::min(n, (b + 1) * kBlockSize); ++e)
      for (const Eigen::Matrix3Xd* p : {&p0_B, &p1_B, &p2_B}) {
        lo = lo.cwiseMin(p->col(e));
        hi = hi.cwiseMax(p->col(e));
        r2 = std::max(r2, p->col(e).squaredNorm());
      }
    block_min_B.col(b) = lo;
    block_max_B.col(b) = hi;
  }
  max_vertex_radius_m = std::sqrt(r2);
}

}  // namespace touchdown::rft
