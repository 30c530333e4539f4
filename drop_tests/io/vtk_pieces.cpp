#include "drop_tests/io/vtk_pieces.h"

#include <array>
#include <map>

namespace touchdown::io {

PadSurfaceMesh MakePadSurfaceMesh(const rft::SurfaceElements& elements) {
  std::map<std::array<double, 3>, int> index;  // exact equality: corners shared by construction are equal
  std::vector<Eigen::Vector3d> points;
  PadSurfaceMesh mesh;
  mesh.triangles.reserve(elements.size());
  const auto point = [&](const Eigen::Vector3d& p) {
    const auto [it, added] = index.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(points.size()));
    if (added) points.push_back(p);
    return it->second;
  };
  for (int i = 0; i < elements.size(); ++i)
    mesh.triangles.push_back({point(elements.p0_B.col(i)), point(elements.p1_B.col(i)), point(elements.p2_B.col(i))});
  mesh.points_B.resize(3, static_cast<Eigen::Index>(points.size()));
  for (size_t i = 0; i < points.size(); ++i) mesh.points_B.col(static_cast<Eigen::Index>(i)) = points[i];
  return mesh;
}

VtkPolyData PadSurfacePiece(const PadSurfaceMesh& mesh, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB,
                            const rft::ElementStresses& s) {
  VtkPolyData piece;
  piece.points.reserve(mesh.points_B.cols());
  for (Eigen::Index i = 0; i < mesh.points_B.cols(); ++i) piece.points.push_back(p_WB + R_WB * mesh.points_B.col(i));
  piece.polygons = mesh.triangles;
  const auto values = [](const auto& v) {
    std::vector<double> out(static_cast<size_t>(v.size()));
    for (Eigen::Index i = 0; i < v.size(); ++i) out[static_cast<size_t>(i)] = static_cast<double>(v[i]);
    return out;
  };
  piece.AddCellField(kPadFieldNames[0], values(s.normal_Pa));
  piece.AddCellField(kPadFieldNames[1], values(s.shear_Pa));
  piece.AddCellField(kPadFieldNames[2], values(s.depth_m));
  piece.AddCellField(kPadFieldNames[3], values(s.leading));
  return piece;
}

VtkPolyData SoilSurfacePiece(const rft::GroundSurface& ground, const Eigen::Vector2d& centre_W, double half_width_m,
                             int cells, const std::function<int(double, double)>& soil_at) {
  VtkPolyData piece;
  const double step = 2.0 * half_width_m / cells;
  const auto xy = [&](double i, double j) {
    return Eigen::Vector2d(centre_W.x() - half_width_m + i * step, centre_W.y() - half_width_m + j * step);
  };
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const Eigen::Vector2d p = xy(i, j);
      piece.points.emplace_back(p.x(), p.y(), ground.Height(p.x(), p.y()));
    }
  std::vector<double> soil;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const int a = j * (cells + 1) + i;
      piece.polygons.push_back({a, a + 1, a + cells + 2, a + cells + 1});  // counter-clockwise seen from above
      const Eigen::Vector2d c = xy(i + 0.5, j + 0.5);
      soil.push_back(soil_at(c.x(), c.y()));
    }
  piece.AddCellField("soil", std::move(soil));
  return piece;
}

}  // namespace touchdown::io
