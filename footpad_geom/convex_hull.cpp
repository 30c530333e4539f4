#include "footpad_geom/convex_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <vector>

namespace touchdown::geom {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// True if four of the points are not coplanar (exact orientation tests).
bool SpansVolume(const std::vector<Point>& p) {
  size_t i1 = 1, i2 = 0;
  while (i1 < p.size() && p[i1] == p[0]) ++i1;
  if (i1 == p.size()) return false;
  for (i2 = i1 + 1; i2 < p.size() && CGAL::collinear(p[0], p[i1], p[i2]); ++i2) {
  }
  if (i2 >= p.size()) return false;
  for (size_t i3 = i2 + 1; i3 < p.size(); ++i3)
    if (CGAL::orientation(p[0], p[i1], p[i2], p[i3]) != CGAL::COPLANAR) return true;
  return false;
}
}  // namespace

Eigen::Matrix3Xd ConvexHullVertices(const Eigen::Matrix3Xd& points) {
  const int n = static_cast<int>(points.cols());
  if (n < 4) return points;
  std::vector<Point> in;
  in.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) in.emplace_back(points(0, i), points(1, i), points(2, i));
  if (!SpansVolume(in)) return points;  // no polytope: every point may be extreme
  std::vector<Point> extreme;
  CGAL::extreme_points_3(in, std::back_inserter(extreme));
  std::sort(extreme.begin(), extreme.end());
  // Keep the input's order (and exact coordinates): the caller's sums do not depend on CGAL's.
  std::vector<int> keep;
  for (int i = 0; i < n; ++i)
    if (std::binary_search(extreme.begin(), extreme.end(), in[static_cast<size_t>(i)])) keep.push_back(i);
  Eigen::Matrix3Xd out(3, static_cast<int>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k) out.col(static_cast<int>(k)) = points.col(keep[k]);
  return out;
}

}  // namespace touchdown::geom
