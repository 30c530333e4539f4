#pragma once
// A pad surface as flat arrays of triangles in the pad frame B (model data, built once by
// footpad_geom from a mesh or a revolved profile). The origin of B is the pad's reference
// point (ball-joint centre or rod attachment): moments are taken about it. Normals point
// out of the pad. Structure-of-arrays so the per-step force loop streams through memory.
#include <Eigen/Core>

namespace touchdown::rft {

struct SurfaceElements {
  Eigen::Matrix3Xd p0_B, p1_B, p2_B;  // triangle vertices [m], counter-clockwise seen from outside
  Eigen::Matrix3Xd n_B;               // unit outward normals
  Eigen::VectorXd area_m2;            // triangle areas [m^2]

  int size() const { return static_cast<int>(area_m2.size()); }
  void Resize(int n) {
    p0_B.resize(3, n);
    p1_B.resize(3, n);
    p2_B.resize(3, n);
    n_B.resize(3, n);
    area_m2.resize(n);
  }
};

}  // namespace touchdown::rft
