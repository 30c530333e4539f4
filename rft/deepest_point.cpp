#include "rft/deepest_point.h"

#include <algorithm>
#include <limits>

namespace touchdown::rft {

double DeepestVertexDepth(const Eigen::Matrix3Xd& vertices_B, const Eigen::Matrix3d& R_WB,
                          const Eigen::Vector3d& p_WB, const GroundSurface& ground) {
  double deepest = -std::numeric_limits<double>::infinity();
  if (const auto* plane = ground.ExactPlane()) {
    // depth(p_W) = h0 + sx x + sy y - z = h0 + g_W . p_W, with p_W = p_WB + R_WB p_B.
    const Eigen::Vector3d g_W(plane->slope_x(), plane->slope_y(), -1.0);
    const double depth0 = plane->height_at_origin_m() + g_W.dot(p_WB);
    const Eigen::Vector3d g_B = R_WB.transpose() * g_W;
    // Column by column: a product over all vertices would allocate its row of depths, and this
    // runs in every right-hand side of a free pad and a lander.
    double highest = -std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < vertices_B.cols(); ++i) highest = std::max(highest, g_B.dot(vertices_B.col(i)));
    if (vertices_B.cols() > 0) deepest = depth0 + highest;
    return deepest;
  }
  for (int i = 0; i < vertices_B.cols(); ++i)
    deepest = std::max(deepest, ground.Depth(p_WB + R_WB * vertices_B.col(i)));
  return deepest;
}

}  // namespace touchdown::rft
