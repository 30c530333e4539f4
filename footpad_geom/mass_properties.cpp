#include "footpad_geom/mass_properties.h"

#include <Eigen/Geometry>

namespace touchdown::geom {

VolumeProperties ComputeVolumeProperties(const TriangleMesh& mesh) {
  VolumeProperties out;
  if (mesh.vertices.empty()) return out;
  // Sum about a point inside the bounding box: coordinates far from the origin would otherwise
  // cancel in the second moments.
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Eigen::Vector3d o = 0.5 * (lo + hi);
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // integral of x x^T dV about o
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o, c = mesh.vertices[t[2]] - o;
    const double v = a.dot(b.cross(c)) / 6.0;
    const Eigen::Vector3d s = a + b + c;
    volume += v;
    first += v * s / 4.0;
    second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  out.volume_m3 = volume;
  if (volume == 0.0) return out;
  const Eigen::Vector3d centroid = first / volume;
  const Eigen::Matrix3d second_com = second - volume * centroid * centroid.transpose();
  out.centroid_m = centroid + o;
  out.inertia_per_density_m5 = second_com.trace() * Eigen::Matrix3d::Identity() - second_com;
  return out;
}

}  // namespace touchdown::geom
