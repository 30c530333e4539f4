#pragma once
// Volume, centroid and inertia of the solid bounded by a closed, outward-oriented triangle
// mesh, at uniform density, by the divergence theorem: the solid is the signed sum of the
// tetrahedra (o, a, b, c) over the triangles, o any fixed point. Per tetrahedron (vertices
// p_k relative to o, one of them o itself, signed volume V):
//   integral of x dV    = V (a + b + c) / 4
//   integral of x x^T dV = V / 20 (a a^T + b b^T + c c^T + s s^T),  s = a + b + c
// (Tonon, J. Math. Stat. 2004). Exact for the polyhedron.
#include <Eigen/Core>

#include "footpad_geom/triangle_mesh.h"

namespace touchdown::geom {

struct VolumeProperties {
  double volume_m3 = 0.0;
  Eigen::Vector3d centroid_m = Eigen::Vector3d::Zero();
  // Inertia tensor about the centroid per unit density [m^5]: multiply by the density.
  Eigen::Matrix3d inertia_per_density_m5 = Eigen::Matrix3d::Zero();
};

VolumeProperties ComputeVolumeProperties(const TriangleMesh& mesh);

}  // namespace touchdown::geom
