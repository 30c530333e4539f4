// Axisymmetric pads as meshes: every profile revolves into a valid closed outward mesh whose
// area and volume converge to the closed forms, with no sliver fan at the axis.
#include "footpad_geom/revolve.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "footpad_geom/mass_properties.h"
#include "footpad_geom/mesh_io.h"
#include "footpad_geom/pad_body_builder.h"
#include "rft/input_error.h"

namespace touchdown::geom {
namespace {

constexpr double kR = 0.05, kH = 0.016;  // the paper's pads: 100 mm diameter, 16 mm thick

double Area(const TriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles)
    a += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
  return a;
}
double Volume(const TriangleMesh& m) { return ComputeVolumeProperties(m).volume_m3; }

// Smallest interior angle over all triangles [deg].
double MinAngleDeg(const TriangleMesh& m) {
  double smallest = 180.0;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = m.vertices[t[(k + 1) % 3]] - m.vertices[t[k]];
      const Eigen::Vector3d b = m.vertices[t[(k + 2) % 3]] - m.vertices[t[k]];
      smallest = std::min(smallest, std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / std::numbers::pi);
    }
  return smallest;
}

struct ShapeCase {
  const char* name;
  AxisymmetricProfile profile;
  double volume, area;  // closed forms of the smooth pad
};

std::vector<ShapeCase> Shapes() {
  const double c = 0.004, R = 0.1, half_angle = 80.0 * std::numbers::pi / 180.0;
  const double cap = R - std::sqrt(R * R - kR * kR);           // cap height
  const double cone = kR / std::tan(half_angle);                // cone height
  const double wall = 2 * std::numbers::pi * kR;                             // side wall area per unit height
  std::vector<ShapeCase> s;
  s.push_back({"flat", MakeFlatProfile(kR, kH), std::numbers::pi * kR * kR * kH, 2 * std::numbers::pi * kR * kR + wall * kH});
  // Chamfer: the cylinder less the ring of triangular section c x c at the rim (Pappus).
  const double ring_centroid = kR - c / 3;
  s.push_back({"chamfer", MakeChamferProfile(kR, kH, c), std::numbers::pi * kR * kR * kH - 2 * std::numbers::pi * ring_centroid * c * c / 2,
               std::numbers::pi * (kR - c) * (kR - c) + std::numbers::pi * (2 * kR - c) * std::sqrt(2.0) * c + wall * (kH - c) + std::numbers::pi * kR * kR});
  s.push_back({"spherical_cap", MakeSphericalCapProfile(kR, kH, R, 400),
               std::numbers::pi * kR * kR * kH - (std::numbers::pi * R * kR * kR - 2 * std::numbers::pi / 3 * (R * R * R - std::pow(R * R - kR * kR, 1.5))),
               2 * std::numbers::pi * R * cap + wall * (kH - cap) + std::numbers::pi * kR * kR});
  s.push_back({"cone", MakeConeProfile(kR, kH, half_angle), std::numbers::pi * kR * kR * (kH - 2 * cone / 3),
               std::numbers::pi * kR * std::hypot(kR, cone) + wall * (kH - cone) + std::numbers::pi * kR * kR});
  return s;
}

TEST(RevolvedPads, AreClosedOutwardAndValid) {
  std::vector<ShapeCase> shapes = Shapes();
  shapes.push_back({"exponential", MakeExponentialProfile(kR, kH, kH / std::expm1(31.9 * kR), 31.9, 400), 0, 0});
  shapes.push_back({"table", MakeTabulatedProfile({{0, 0}, {0.02, 0}, {0.04, 0.003}, {kR, 0.01}}, kH), 0, 0});
  for (const ShapeCase& s : shapes) {
    SCOPED_TRACE(s.name);
    const TriangleMesh mesh = RevolveProfileToMesh(s.profile, 64);
    // Preparing it changes nothing: closed, manifold, outward, no degenerate or crossing faces.
    const PreparedMesh prepared = PrepareTriangleMesh(ToPolygonSoup(mesh), s.name);
    EXPECT_FALSE(prepared.reoriented);
    EXPECT_EQ(prepared.merged_points, 0);
    EXPECT_EQ(prepared.mesh.triangles.size(), mesh.triangles.size());
    EXPECT_GT(Volume(mesh), 0.0);
    // Lowest point on the axis at the origin, top at h.
    double lo = 1, hi = -1;
    for (const auto& v : mesh.vertices) lo = std::min(lo, v.z()), hi = std::max(hi, v.z());
    EXPECT_DOUBLE_EQ(lo, 0.0);
    EXPECT_DOUBLE_EQ(hi, kH);
    // No needles at the axis: rings near it have few vertices.
    EXPECT_GT(MinAngleDeg(mesh), 5.0);
  }
}

TEST(RevolvedPads, FlatPadIsTheInscribedPolygonPrism) {
  // The bottom and top are planar triangulations of the rim polygon, so the volume is exact.
  for (int n : {6, 16, 100, 128}) {
    const TriangleMesh mesh = RevolveProfileToMesh(MakeFlatProfile(kR, kH), n);
    const double polygon = 0.5 * n * kR * kR * std::sin(2 * std::numbers::pi / n);
    EXPECT_NEAR(Volume(mesh), polygon * kH, 1e-12 * polygon * kH) << n;
    EXPECT_NEAR(Area(mesh), 2 * polygon + n * 2 * kR * std::sin(std::numbers::pi / n) * kH, 1e-12) << n;
  }
}

// The area-preserving rim: every horizontal section has its circle's area, so a flat pad's bottom
// (a planar triangulation of the rim n-gon) is pi r^2 and its volume pi r^2 h at any n; the
// side wall is the scaled n-gon's perimeter, 2 n r s sin(pi / n) with s = sqrt((2 pi / n) / sin(2 pi / n)).
TEST(RevolvedPads, AreaPreservingRimHasTheCirclesArea) {
  const double pi = std::numbers::pi;
  for (int n : {6, 12, 16, 24, 100, 128}) {
    const double s = AreaPreservingRadiusScale(n);
    EXPECT_NEAR(0.5 * n * std::pow(s * kR, 2) * std::sin(2 * pi / n), pi * kR * kR, 1e-12 * pi * kR * kR) << n;
    const TriangleMesh mesh = RevolveProfileToMesh(MakeFlatProfile(kR, kH), n, RimPolygon::kAreaPreserving);
    EXPECT_NEAR(Volume(mesh), pi * kR * kR * kH, 1e-12 * pi * kR * kR * kH) << n;
    EXPECT_NEAR(Area(mesh), 2 * pi * kR * kR + n * 2 * s * kR * std::sin(pi / n) * kH, 1e-12) << n;
    double bottom = 0.0;  // the bottom alone: the triangles at z = 0
    for (const auto& t : mesh.triangles)
      if (mesh.vertices[t[0]].z() == 0.0 && mesh.vertices[t[1]].z() == 0.0 && mesh.vertices[t[2]].z() == 0.0)
        bottom += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
    EXPECT_NEAR(bottom, pi * kR * kR, 1e-12 * pi * kR * kR) << n;
    // Still closed, outward and valid; the lowest point stays on the axis at the origin.
    const PreparedMesh prepared = PrepareTriangleMesh(ToPolygonSoup(mesh), "area_preserving");
    EXPECT_FALSE(prepared.reoriented);
    EXPECT_EQ(prepared.mesh.triangles.size(), mesh.triangles.size());
  }
  // The inscribed rim is the default and unchanged: vertex for vertex the mesh above.
  const TriangleMesh plain = RevolveProfileToMesh(MakeFlatProfile(kR, kH), 24);
  const TriangleMesh inscribed = RevolveProfileToMesh(MakeFlatProfile(kR, kH), 24, RimPolygon::kInscribed);
  ASSERT_EQ(plain.vertices.size(), inscribed.vertices.size());
  for (std::size_t i = 0; i < plain.vertices.size(); ++i) EXPECT_EQ(plain.vertices[i], inscribed.vertices[i]);
}

TEST(RevolvedPads, AreaAndVolumeConvergeToClosedForms) {
  for (const ShapeCase& s : Shapes()) {
    SCOPED_TRACE(s.name);
    double previous_volume_error = 1.0, previous_area_error = 1.0;
    for (int n : {32, 64, 128, 256}) {
      const TriangleMesh mesh = RevolveProfileToMesh(s.profile, n);
      const double volume_error = std::abs(Volume(mesh) / s.volume - 1);
      const double area_error = std::abs(Area(mesh) / s.area - 1);
      // Inscribed polygon: the error is O(1/n^2), (2 pi / n)^2 / 6 for the disc.
      EXPECT_LT(volume_error, 1.5 * std::pow(2 * std::numbers::pi / n, 2) / 6 + 1e-5) << n;
      EXPECT_LT(area_error, 1.5 * std::pow(2 * std::numbers::pi / n, 2) / 6 + 1e-5) << n;
      EXPECT_LT(volume_error, previous_volume_error);
      EXPECT_LT(area_error, previous_area_error);
      previous_volume_error = volume_error;
      previous_area_error = area_error;
    }
  }
}

TEST(RevolvedPads, FineProfilesAreThinnedToTheAngularError) {
  // 400 profile pieces need far fewer rings at 128 segments; the volume stays within the
  // angular discretisation error of the exact (400-piece) polyline's solid (Pappus).
  const AxisymmetricProfile curved = MakeExponentialProfile(kR, kH, kH / std::expm1(31.9 * kR), 31.9, 400);
  double pappus = 0.0;  // volume between the profile polyline and the top, 2 pi x-bar dA
  for (std::size_t i = 1; i < curved.points.size(); ++i) {
    const ProfilePoint a = curved.points[i - 1], b = curved.points[i];
    // Trapezoid of the strip x in [a.x, b.x] between u(x) and h, revolved (exact for a line).
    const double dx = b.x_m - a.x_m, ha = kH - a.u_m, hb = kH - b.u_m;
    pappus += 2 * std::numbers::pi * dx * (ha * (2 * a.x_m + b.x_m) + hb * (a.x_m + 2 * b.x_m)) / 6;
  }
  const TriangleMesh mesh = RevolveProfileToMesh(curved, 128);
  EXPECT_NEAR(Volume(mesh) / pappus, 1.0, 3 * std::pow(2 * std::numbers::pi / 128, 2) / 6);
  EXPECT_LT(mesh.triangles.size(), 40000u);
}

TEST(RevolvedPads, BodyHasTheCylindersMassProperties) {
  const double m = 1.6;
  const PadBody body = RevolveProfileToBody(MakeFlatProfile(kR, kH), 256, m, Eigen::Vector3d(0, 0, kH));
  EXPECT_DOUBLE_EQ(body.mass_kg, m);
  EXPECT_NEAR(body.com_B.head<2>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(body.com_B.z(), -kH / 2, 1e-12);
  EXPECT_NEAR(body.lowest_z_B, -kH, 1e-15);
  const double ixx = m * (3 * kR * kR + kH * kH) / 12, izz = m * kR * kR / 2;
  EXPECT_NEAR(body.inertia_com_B(0, 0) / ixx, 1.0, 2e-4);
  EXPECT_NEAR(body.inertia_com_B(1, 1) / ixx, 1.0, 2e-4);
  EXPECT_NEAR(body.inertia_com_B(2, 2) / izz, 1.0, 2e-4);
  EXPECT_NEAR(body.inertia_com_B(0, 1), 0.0, 1e-12 * izz);
  EXPECT_NEAR(body.inertia_com_B(0, 2), 0.0, 1e-12 * izz);
  // Elements: the closed surface's vector area vanishes; the bottom faces look straight down.
  const rft::SurfaceElements& e = body.surface;
  Eigen::Vector3d vector_area = Eigen::Vector3d::Zero();
  for (int i = 0; i < e.size(); ++i) {
    vector_area += e.area_m2(i) * e.n_B.col(i);
    EXPECT_NEAR(e.n_B.col(i).norm(), 1.0, 1e-12);
    if (std::max({e.p0_B(2, i), e.p1_B(2, i), e.p2_B(2, i)}) < -kH + 1e-12) {
      EXPECT_NEAR(e.n_B(2, i), -1.0, 1e-12);
    }
  }
  EXPECT_LT(vector_area.norm(), 1e-12 * e.area_m2.sum());
}

TEST(RevolvedPads, TooFewSegmentsOrAVolumelessProfileAreRefused) {
  try {
    RevolveProfileToMesh(MakeFlatProfile(kR, kH), 5);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "angular_segments: must be >= 6, got 5");
  }
}

}  // namespace
}  // namespace touchdown::geom
