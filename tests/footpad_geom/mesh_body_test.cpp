// Mass properties against closed forms, pad bodies from meshes, and isotropic remeshing.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "footpad_geom/mass_properties.h"
#include "footpad_geom/mesh_io.h"
#include "footpad_geom/mesh_remesh.h"
#include "footpad_geom/pad_body_builder.h"
#include "footpad_geom/revolve.h"
#include "rft/input_error.h"
#include "tests/footpad_geom/mesh_test_shapes.h"

namespace touchdown::geom {
namespace {


TriangleMesh Box(double a, double b, double c, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  return PrepareTriangleMesh(testing::BoxSoup(a, b, c, offset), "box").mesh;
}

TEST(MassProperties, BoxMatchesClosedForm) {
  const double a = 0.3, b = 0.2, c = 0.05;
  const Eigen::Vector3d offset(10.0, -4.0, 2.0);  // far from the origin: no cancellation
  const VolumeProperties vp = ComputeVolumeProperties(Box(a, b, c, offset));
  const double v = a * b * c;
  EXPECT_NEAR(vp.volume_m3, v, 1e-14);
  EXPECT_TRUE(vp.centroid_m.isApprox(offset + Eigen::Vector3d(a, b, c) / 2, 1e-13));
  const Eigen::Vector3d diagonal = v / 12 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b);
  EXPECT_LT((vp.inertia_per_density_m5 - Eigen::Matrix3d(diagonal.asDiagonal())).norm(), 1e-12 * diagonal.norm());
}

TEST(MassProperties, RotatedBoxGivesTheRotatedTensor) {
  // Products of inertia carry the tensor's sign convention: I = R I_principal R^T.
  const double a = 0.3, b = 0.2, c = 0.05;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  TriangleMesh box = Box(a, b, c);
  for (auto& v : box.vertices) v = R * v;
  const VolumeProperties vp = ComputeVolumeProperties(box);
  const double v = a * b * c;
  const Eigen::Matrix3d principal =
      (v / 12 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b)).asDiagonal();
  EXPECT_LT((vp.inertia_per_density_m5 - R * principal * R.transpose()).norm(), 1e-12 * principal.norm());
  EXPECT_TRUE(vp.centroid_m.isApprox(R * Eigen::Vector3d(a, b, c) / 2, 1e-12));
}

TEST(PadBodies, MassOrDensityFixTheBody) {
  const TriangleMesh box = Box(0.1, 0.1, 0.02);
  PadMassModel by_mass;
  by_mass.mass_kg = 2.0;
  const PadBody body = MakePadBody(box, by_mass, Eigen::Vector3d(0.05, 0.05, 0.02), "box");
  EXPECT_DOUBLE_EQ(body.mass_kg, 2.0);
  EXPECT_TRUE(body.com_B.isApprox(Eigen::Vector3d(0, 0, -0.01), 1e-12));
  EXPECT_NEAR(body.lowest_z_B, -0.02, 1e-15);
  EXPECT_NEAR(body.inertia_com_B(2, 2), 2.0 * (0.01 + 0.01) / 12, 1e-15);
  EXPECT_EQ(body.surface.size(), 12);
  EXPECT_NEAR(body.surface.area_m2.sum(), 2 * 0.01 + 4 * 0.002, 1e-15);
  PadMassModel by_density;
  by_density.density_kg_m3 = 1000.0;
  EXPECT_NEAR(MakePadBody(box, by_density, Eigen::Vector3d::Zero(), "box").mass_kg, 0.2, 1e-14);
  PadMassModel explicit_inertia = by_mass;
  explicit_inertia.inertia_com_kg_m2 = Eigen::Vector3d(0.01, 0.02, 0.025).asDiagonal();
  explicit_inertia.center_of_mass_m = Eigen::Vector3d(0.05, 0.05, 0.005);  // ballast low down
  const PadBody ballasted = MakePadBody(box, explicit_inertia, Eigen::Vector3d(0.05, 0.05, 0.02), "box");
  EXPECT_TRUE(ballasted.com_B.isApprox(Eigen::Vector3d(0, 0, -0.015), 1e-12));
  EXPECT_DOUBLE_EQ(ballasted.inertia_com_B(2, 2), 0.025);
}

TEST(PadBodies, InconsistentMassModelsAreRefused) {
  const TriangleMesh box = Box(0.1, 0.1, 0.02);
  auto error = [&](const PadMassModel& m) {
    try {
      MakePadBody(box, m, Eigen::Vector3d::Zero(), "pad.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  PadMassModel none;
  EXPECT_EQ(error(none), "pad.yaml: mass_kg: give exactly one of mass_kg and density_kg_m3");
  PadMassModel both = none;
  both.mass_kg = 1.0;
  both.density_kg_m3 = 1.0;
  EXPECT_EQ(error(both), "pad.yaml: mass_kg: give exactly one of mass_kg and density_kg_m3");
  PadMassModel flat_inertia;
  flat_inertia.mass_kg = 1.0;
  flat_inertia.inertia_com_kg_m2 = Eigen::Vector3d(0.01, 0.01, 0.03).asDiagonal();
  EXPECT_NE(error(flat_inertia).find("pad.yaml: inertia_kg_m2: is not a rigid body's inertia"), std::string::npos)
      << error(flat_inertia);
  PadMassModel com_only;
  com_only.mass_kg = 1.0;
  com_only.center_of_mass_m = Eigen::Vector3d::Zero();
  EXPECT_NE(error(com_only).find("needs the inertia"), std::string::npos);
}

TEST(Remeshing, KeepsTheVolumeAndEvensTheEdges) {
  struct Case {
    const char* name;
    TriangleMesh mesh;
    double edge;
  };
  const Case cases[] = {
      {"box", Box(0.1, 0.08, 0.016), 0.004},
      {"flat pad", RevolveProfileToMesh(MakeFlatProfile(0.05, 0.016), 64), 0.004},
      {"C4 pad", RevolveProfileToMesh(MakeChamferProfile(0.05, 0.016, 0.004), 64), 0.003},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const double volume = ComputeVolumeProperties(c.mesh).volume_m3;
    const TriangleMesh remeshed = PrepareTriangleMesh(ToPolygonSoup(RemeshIsotropic(c.mesh, c.edge)), c.name).mesh;
    EXPECT_NEAR(ComputeVolumeProperties(remeshed).volume_m3 / volume, 1.0, 5e-3);
    // Edges end up near the target: none more than twice as long.
    double longest = 0.0, sum = 0.0;
    int count = 0;
    for (const auto& t : remeshed.triangles)
      for (int k = 0; k < 3; ++k) {
        const double l = (remeshed.vertices[t[k]] - remeshed.vertices[t[(k + 1) % 3]]).norm();
        longest = std::max(longest, l);
        sum += l;
        ++count;
      }
    EXPECT_LT(longest, 2.0 * c.edge);
    EXPECT_NEAR(sum / count / c.edge, 1.0, 0.35);
  }
}

class RemeshedFiles : public testing::TempDirTest {};

TEST_F(RemeshedFiles, LoadingWithRemeshingValidatesTheResult) {
  const std::string path = Write("box.off", testing::OffText(testing::BoxSoup(100, 80, 16)));
  const PreparedMesh coarse = LoadTriangleMesh(path, {LengthUnit::kMillimetre, 0.0});
  const PreparedMesh fine = LoadTriangleMesh(path, {LengthUnit::kMillimetre, 0.005});
  EXPECT_EQ(coarse.mesh.triangles.size(), 12u);
  EXPECT_GT(fine.mesh.triangles.size(), 200u);
  EXPECT_NEAR(ComputeVolumeProperties(fine.mesh).volume_m3, 0.1 * 0.08 * 0.016, 1e-3 * 0.1 * 0.08 * 0.016);
}

}  // namespace
}  // namespace touchdown::geom
