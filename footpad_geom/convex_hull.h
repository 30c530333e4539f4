#pragma once
// The vertices of the convex hull of a point set (CGAL's extreme points, exact predicates).
// Over a plane the deepest point of a rigid body is a support point in the direction of the
// depth gradient, and a support point is always a hull vertex: searching these is enough.
#include <Eigen/Core>

namespace touchdown::geom {

// Columns of `points` that are vertices of their convex hull, in their original order. A set
// with no 3D hull (fewer than four points, or all coplanar) is returned whole.
Eigen::Matrix3Xd ConvexHullVertices(const Eigen::Matrix3Xd& points);

}  // namespace touchdown::geom
