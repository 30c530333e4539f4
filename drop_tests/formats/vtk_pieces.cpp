#include "drop_tests/formats/vtk_pieces.h"
#include "rft/units.h"

#include <algorithm>
#include <array>
#include <cmath>
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
  mesh.area_m2 = elements.area_m2;
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
  // The vectors: the same forces that give the stresses (normal_stress_Pa = -traction . n).
  const size_t n = mesh.triangles.size();
  std::vector<double> traction(3 * n), force(3 * n);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Index e = static_cast<Eigen::Index>(i);
    const double area = mesh.area_m2[e];
    for (int c = 0; c < 3; ++c) {
      force[3 * i + c] = s.force_W(c, e);
      traction[3 * i + c] = area > 0.0 ? s.force_W(c, e) / area : 0.0;
    }
  }
  piece.AddCellField(kPadFieldNames[4], std::move(traction), 3);
  piece.AddCellField(kPadFieldNames[5], std::move(force), 3);
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

CraterSurface::CraterSurface(const rft::GroundSurface& ground, const Eigen::Vector2d& lo_W, const Eigen::Vector2d& hi_W,
                             int step_mm)
    : step_mm_(step_mm) {
  const double step = step_mm / units::kMmPerM;
  i0_ = static_cast<int>(std::floor(lo_W.x() / step));
  j0_ = static_cast<int>(std::floor(lo_W.y() / step));
  nx_ = std::max(1, static_cast<int>(std::ceil(hi_W.x() / step)) - i0_);
  ny_ = std::max(1, static_cast<int>(std::ceil(hi_W.y() / step)) - j0_);
  surface_z_.resize(static_cast<size_t>((nx_ + 1) * (ny_ + 1)));
  for (int j = 0; j <= ny_; ++j)
    for (int i = 0; i <= nx_; ++i) surface_z_[Index(i, j)] = ground.Height(X(i), Y(j));
  z_ = surface_z_;
}

int CraterSurface::StepFor(double pad_radius_m) {
  return std::max(1, static_cast<int>(std::lround(pad_radius_m * units::kMmPerM / 14.0)));
}

void CraterSurface::Press(const PadSurfaceMesh& mesh, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB) {
  const double step = step_mm_ / units::kMmPerM;
  const Eigen::Matrix3Xd p_W = (R_WB * mesh.points_B).colwise() + p_WB;
  // Each triangle's plane over the grid points inside its projection; walls seen edge-on (no
  // projected area) are skipped, their neighbours cover their points.
  for (const std::vector<int>& t : mesh.triangles) {
    const Eigen::Vector3d a = p_W.col(t[0]), b = p_W.col(t[1]), c = p_W.col(t[2]);
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (std::abs(det) < 1e-18) continue;
    const int i_lo = std::max(0, static_cast<int>(std::ceil(std::min({a.x(), b.x(), c.x()}) / step)) - i0_);
    const int i_hi = std::min(nx_, static_cast<int>(std::floor(std::max({a.x(), b.x(), c.x()}) / step)) - i0_);
    const int j_lo = std::max(0, static_cast<int>(std::ceil(std::min({a.y(), b.y(), c.y()}) / step)) - j0_);
    const int j_hi = std::min(ny_, static_cast<int>(std::floor(std::max({a.y(), b.y(), c.y()}) / step)) - j0_);
    for (int j = j_lo; j <= j_hi; ++j)
      for (int i = i_lo; i <= i_hi; ++i) {
        const double x = X(i) - a.x(), y = Y(j) - a.y();
        const double u = (x * (c.y() - a.y()) - (c.x() - a.x()) * y) / det;  // barycentric weight of b
        const double v = ((b.x() - a.x()) * y - x * (b.y() - a.y())) / det;  // of c
        constexpr double kEdge = 1e-12;  // a point on an edge belongs to both triangles
        if (u < -kEdge || v < -kEdge || u + v > 1.0 + kEdge) continue;
        double& z = z_[Index(i, j)];
        z = std::min(z, a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z()));
      }
  }
}

VtkPolyData CraterSurface::Piece() const {
  VtkPolyData piece;
  std::vector<double> depth;
  for (int j = 0; j <= ny_; ++j)
    for (int i = 0; i <= nx_; ++i) {
      piece.points.emplace_back(X(i), Y(j), z_[Index(i, j)]);
      depth.push_back(surface_z_[Index(i, j)] - z_[Index(i, j)]);
    }
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) piece.polygons.push_back({Index(i, j), Index(i + 1, j), Index(i + 1, j + 1), Index(i, j + 1)});
  piece.AddPointField("crater_depth_m", std::move(depth));
  return piece;
}

}  // namespace touchdown::io
