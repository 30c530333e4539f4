#pragma once
// Hand-built triangulated test geometry for the 3D contact tests (no CGAL, no files): boxes,
// thin plates and pads revolved from a profile with N sectors. Normals and areas come from the
// triangles' cross products, vertices counter-clockwise seen from outside.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "rft/surface_elements.h"

namespace touchdown::rft::testing {

class MeshBuilder {
 public:
  void Add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    if ((b - a).cross(c - a).norm() == 0.0) return;  // degenerate (a revolved piece on the axis)
    tri_.push_back({a, b, c});
  }
  // Quad a-b-c-d counter-clockwise seen from outside.
  void AddQuad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
               const Eigen::Vector3d& d) {
    Add(a, b, c);
    Add(a, c, d);
  }
  int size() const { return static_cast<int>(tri_.size()); }
  SurfaceElements Build() const {
    SurfaceElements s;
    s.Resize(size());
    for (int i = 0; i < size(); ++i) {
      const auto& t = tri_[i];
      const Eigen::Vector3d c = (t[1] - t[0]).cross(t[2] - t[0]);
      s.p0_B.col(i) = t[0];
      s.p1_B.col(i) = t[1];
      s.p2_B.col(i) = t[2];
      s.n_B.col(i) = c.normalized();
      s.area_m2(i) = 0.5 * c.norm();
    }
    return s;
  }

 private:
  std::vector<std::array<Eigen::Vector3d, 3>> tri_;
};

// Axis-aligned box [lo, hi], each face split into nx x ny quads (so rows of triangles exist).
inline SurfaceElements MakeBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int divisions = 1) {
  MeshBuilder m;
  // For each axis a and side s, a face with outward normal s e_a; u, v span it so that
  // u x v = s e_a (counter-clockwise from outside).
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      int ua = (a + 1) % 3, va = (a + 2) % 3;
      if (side == 0) std::swap(ua, va);
      const double fixed = side == 0 ? lo(a) : hi(a);
      for (int i = 0; i < divisions; ++i) {
        for (int j = 0; j < divisions; ++j) {
          auto corner = [&](int di, int dj) {
            Eigen::Vector3d p;
            p(a) = fixed;
            p(ua) = lo(ua) + (hi(ua) - lo(ua)) * (i + di) / divisions;
            p(va) = lo(va) + (hi(va) - lo(va)) * (j + dj) / divisions;
            return p;
          };
          m.AddQuad(corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
        }
      }
    }
  }
  return m.Build();
}

// A pad revolved about z from a profile (x = radius, u = height above the lowest point, from
// (0, 0) out along the bottom and up the side wall to (r, h)), with `sectors` sectors and a
// flat top face at u = h. The lowest point is the origin of B.
inline SurfaceElements MakeRevolvedPad(const std::vector<std::pair<double, double>>& profile, int sectors) {
  MeshBuilder m;
  auto at = [&](double x, double u, int j) {
    const double th = 2.0 * std::numbers::pi * j / sectors;
    return Eigen::Vector3d(x * std::cos(th), x * std::sin(th), u);
  };
  for (size_t k = 0; k + 1 < profile.size(); ++k) {
    const auto [x0, u0] = profile[k];
    const auto [x1, u1] = profile[k + 1];
    for (int j = 0; j < sectors; ++j) {
      // A, B at the inner end (sector start, end), C, D at the outer end (end, start).
      const Eigen::Vector3d A = at(x0, u0, j), B = at(x0, u0, j + 1), C = at(x1, u1, j + 1),
                            D = at(x1, u1, j);
      m.Add(A, C, D);
      m.Add(A, B, C);
    }
  }
  const auto [r, h] = profile.back();
  for (int j = 0; j < sectors; ++j) m.Add(Eigen::Vector3d(0, 0, h), at(r, h, j), at(r, h, j + 1));
  return m.Build();
}

// Flat pad of radius r and thickness h whose side wall is split into `wall_rows` rows.
inline std::vector<std::pair<double, double>> FlatProfile(double r, double h, int wall_rows = 1) {
  std::vector<std::pair<double, double>> p = {{0.0, 0.0}, {r, 0.0}};
  for (int i = 1; i <= wall_rows; ++i) p.push_back({r, h * i / wall_rows});
  return p;
}

inline Eigen::Matrix3d RotX(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
inline Eigen::Matrix3d RotY(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
// A flat pad like the lander's (27.5 mm radius, 10 mm thick, its bottom 20 mm below the reference
// point) with its bottom in three rings and its wall in two rows, so blocks hold one face each and
// each face is several runs of equal normals; bounds filled.
inline SurfaceElements LanderLikeFlatPad(int sectors) {
  const double r = 0.0275, h = 0.010;
  SurfaceElements pad =
      MakeRevolvedPad({{0.0, 0.0}, {r / 3, 0.0}, {2 * r / 3, 0.0}, {r, 0.0}, {r, h / 2}, {r, h}}, sectors);
  for (int e = 0; e < pad.size(); ++e)
    for (Eigen::Matrix3Xd* p : {&pad.p0_B, &pad.p1_B, &pad.p2_B}) p->col(e).z() -= 0.020;
  pad.UpdateBounds();
  return pad;
}

inline Eigen::Matrix3d RotZ(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

}  // namespace touchdown::rft::testing
