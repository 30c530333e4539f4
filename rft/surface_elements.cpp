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
  UpdateBlockCones();

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

void SurfaceElements::UpdateBlockCones() {
  const int n = size();
  block_normal_axis_B.resize(3, block_count());
  block_centre_B.resize(3, block_count());
  block_normal_spread.resize(block_count());
  block_radius_m.resize(block_count());
  for (int b = 0; b < block_count(); ++b) {
    const int first = b * kBlockSize, last = std::min(n, (b + 1) * kBlockSize);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int e = first; e < last; ++e) sum += n_B.col(e);
    // A block whose normals cancel (no useful axis) gets spread 2: no normal is excluded, so the
    // block is never skipped.
    const double norm = sum.norm();
    const Eigen::Vector3d axis = norm > 0.0 ? Eigen::Vector3d(sum / norm) : Eigen::Vector3d::UnitZ();
    double spread = norm > 0.0 ? 0.0 : 2.0;
    for (int e = first; e < last; ++e) spread = std::max(spread, (n_B.col(e) - axis).norm());
    const Eigen::Vector3d centre = 0.5 * (block_min_B.col(b) + block_max_B.col(b));
    double radius = 0.0;
    for (int e = first; e < last; ++e)
      for (const Eigen::Matrix3Xd* p : {&p0_B, &p1_B, &p2_B}) radius = std::max(radius, (p->col(e) - centre).norm());
    block_normal_axis_B.col(b) = axis;
    block_normal_spread[b] = spread;
    block_centre_B.col(b) = centre;
    block_radius_m[b] = radius;
  }
}

}  // namespace touchdown::rft
