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

  // Derived bounds, filled by UpdateBounds() once the arrays above are final (model data, like
  // them). The contact sum uses them to skip whole blocks of kBlockSize consecutive elements
  // that lie above the ground, and to tell a spinning pad from a translating one without a pass
  // over the vertices. Not filled (or stale in size): the contact visits every element and
  // measures the radius itself; the result is the same either way.
  static constexpr int kBlockSize = 32;
  Eigen::Matrix3Xd block_min_B, block_max_B;  // axis-aligned box of each block's vertices [m]
  // Each block's normal cone and extent, so that a rotating pad's contact can skip a block whose
  // every element trails the motion (the top of a buried pad sinking, the back of one sliding)
  // without a pass over its elements: the unit axis of the cone, the largest distance |n - axis|
  // of a normal from it, and the centre of the block's box with the largest vertex distance from it.
  Eigen::Matrix3Xd block_normal_axis_B, block_centre_B;
  Eigen::VectorXd block_normal_spread, block_radius_m;
  double max_vertex_radius_m = -1.0;          // largest |p_B| over all vertices [m]; < 0: unknown
  // Elements whose normals agree to kSameNormal share a class (at most kMaxNormalClasses; -1 for
  // the rest): a pad translating evaluates the stress law once per class rather than once per run
  // of consecutive equal normals (the side wall of a revolved pad repeats its 64 normals band after
  // band). The law sees the class's normal, the first such element's.
  static constexpr int kMaxNormalClasses = 256;
  static constexpr double kSameNormal = 1e-12;  // 1-norm
  Eigen::VectorXi normal_class;
  Eigen::Matrix3Xd class_normal_B;

  int size() const { return static_cast<int>(area_m2.size()); }
  int block_count() const { return (size() + kBlockSize - 1) / kBlockSize; }
  bool HasBounds() const {
    return max_vertex_radius_m >= 0.0 && block_min_B.cols() == block_count() &&
           block_normal_axis_B.cols() == block_count() && normal_class.size() == size();
  }
  void Resize(int n) {
    p0_B.resize(3, n);
    p1_B.resize(3, n);
    p2_B.resize(3, n);
    n_B.resize(3, n);
    area_m2.resize(n);
    block_min_B.resize(3, 0);
    block_max_B.resize(3, 0);
    block_normal_axis_B.resize(3, 0);
    block_centre_B.resize(3, 0);
    block_normal_spread.resize(0);
    block_radius_m.resize(0);
    max_vertex_radius_m = -1.0;
    normal_class.resize(0);
    class_normal_B.resize(3, 0);
  }
  void UpdateBounds();

 private:
  void UpdateBlockCones();  // the block cones and extents, from the boxes UpdateBounds found
};

}  // namespace touchdown::rft
