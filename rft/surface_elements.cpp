#include "rft/surface_elements.h"

#include <algorithm>
#include <array>
#include <map>
#include <vector>
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

  // Normal classes: candidates found through a grid of 1e-9 cells (a normal near a cell face may
  // miss its class and open another one: a cache miss, never a wrong match).
  normal_class.setConstant(n, -1);
  std::vector<Eigen::Vector3d> representatives;
  std::map<std::array<long long, 3>, std::vector<int>> cells;
  for (int e = 0; e < n; ++e) {
    const Eigen::Vector3d v = n_B.col(e);
    const std::array<long long, 3> key{std::llround(v.x() * 1e9), std::llround(v.y() * 1e9), std::llround(v.z() * 1e9)};
    std::vector<int>& bucket = cells[key];
    for (int c : bucket)
      if ((representatives[static_cast<size_t>(c)] - v).cwiseAbs().sum() <= kSameNormal) {
        normal_class[e] = c;
        break;
      }
    if (normal_class[e] < 0 && static_cast<int>(representatives.size()) < kMaxNormalClasses) {
      normal_class[e] = static_cast<int>(representatives.size());
      bucket.push_back(normal_class[e]);
      representatives.push_back(v);
    }
  }
  class_normal_B.resize(3, static_cast<int>(representatives.size()));
  for (size_t c = 0; c < representatives.size(); ++c) class_normal_B.col(static_cast<int>(c)) = representatives[c];
}

}  // namespace touchdown::rft
