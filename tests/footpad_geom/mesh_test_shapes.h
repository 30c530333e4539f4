#pragma once
// Small closed (and deliberately broken) meshes for the footpad_geom mesh tests, and a
// per-test temporary directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "footpad_geom/triangle_mesh.h"

namespace touchdown::geom::testing {

// Axis-aligned box [0, a] x [0, b] x [0, c] shifted by `offset`, as six outward quads.
inline PolygonSoup BoxSoup(double a, double b, double c, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  PolygonSoup s;
  for (int k = 0; k < 8; ++k) {
    const int bit_x = ((k + 1) / 2) % 2, bit_y = (k / 2) % 2;  // 0,1,1,0 around the bottom
    s.vertices.push_back(offset + Eigen::Vector3d(bit_x * a, bit_y * b, (k / 4) * c));
  }
  s.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  return s;
}

// The same box with every quad split into two triangles.
inline PolygonSoup TriangulatedBox(double a = 1, double b = 1, double c = 1,
                                   const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  PolygonSoup quads = BoxSoup(a, b, c, offset), s;
  s.vertices = quads.vertices;
  for (const auto& q : quads.faces) {
    s.faces.push_back({q[0], q[1], q[2]});
    s.faces.push_back({q[0], q[2], q[3]});
  }
  return s;
}

// Two soups as one.
inline PolygonSoup Union(PolygonSoup a, const PolygonSoup& b) {
  const int shift = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto f : b.faces) {
    for (int& i : f) i += shift;
    a.faces.push_back(f);
  }
  return a;
}

inline TriangleMesh ToTriangles(const PolygonSoup& s) {
  TriangleMesh m;
  m.vertices = s.vertices;
  for (const auto& f : s.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) m.triangles.push_back({f[0], f[k], f[k + 1]});
  return m;
}

inline std::string OffText(const PolygonSoup& s) {
  std::string t = "OFF\n" + std::to_string(s.vertices.size()) + " " + std::to_string(s.faces.size()) + " 0\n";
  for (const auto& v : s.vertices) {
    char line[128];
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", v.x(), v.y(), v.z());
    t += line;
  }
  for (const auto& f : s.faces) {
    t += std::to_string(f.size());
    for (int i : f) {
      t += ' ';
      t += std::to_string(i);
    }
    t += '\n';
  }
  return t;
}

// A per-test directory under the system temp dir, removed afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("touchdown_mesh_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& bytes) {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  std::filesystem::path dir_;
};

}  // namespace touchdown::geom::testing
