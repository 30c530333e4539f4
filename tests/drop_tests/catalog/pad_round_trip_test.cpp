// Pad files: every bundled pad (axisymmetric shapes and the hex mesh pad), and pads that use the
// other shapes and every optional field, loaded, written with WritePad and loaded again give the
// same pad (profile, body, mass distribution); a second write is the same text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "drop_tests/catalog/catalog.h"
#include "tests/round_trip.h"

namespace touchdown::io {
namespace {

namespace fs = std::filesystem;

struct PadRoundTrip : testing_scratch::ScratchDirTest {
  void SetUp() override {
    ScratchDirTest::SetUp();
    fs::create_directories(dir_ / "out");
  }
};

void ExpectSamePad(const PadSpec& a, const PadSpec& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.mass_kg, b.mass_kg);
  EXPECT_EQ(a.file.description, b.file.description);
  ASSERT_EQ(a.profile.points.size(), b.profile.points.size());
  for (size_t i = 0; i < a.profile.points.size(); ++i) {
    EXPECT_EQ(a.profile.points[i].x_m, b.profile.points[i].x_m);
    EXPECT_EQ(a.profile.points[i].u_m, b.profile.points[i].u_m);
  }
  EXPECT_EQ(fs::weakly_canonical(a.mesh_file), fs::weakly_canonical(b.mesh_file));
  EXPECT_EQ(a.body.mass_kg, b.body.mass_kg);
  EXPECT_EQ(a.body.surface.size(), b.body.surface.size());
  EXPECT_EQ(a.body.vertices_B, b.body.vertices_B);
  EXPECT_EQ(a.body.com_B, b.body.com_B);
  EXPECT_EQ(a.body.inertia_com_B, b.body.inertia_com_B);
  EXPECT_EQ(a.body.lowest_z_B, b.body.lowest_z_B);
}

// Both copies in out/, away from the files they came from (a mesh is named from there).
void RoundTrip(const PadSpec& loaded, const std::string& first, const std::string& second) {
  testing_scratch::ExpectRoundTrip(
      loaded, first, second, WritePad, [](const std::string& path) { return LoadPad(path); }, ExpectSamePad);
}

TEST_F(PadRoundTrip, BundledPads) {
  int pads = 0;
  for (const auto& entry : fs::directory_iterator(DataDirectory() + "/pads")) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    RoundTrip(LoadPad(name), Path("out/" + name + "_1.yaml"), Path("out/" + name + "_2.yaml"));
    ++pads;
  }
  EXPECT_GE(pads, 4);  // flat, c4, curved, hex
  EXPECT_NE(Slurp(Path("out/hex_1.yaml")).find("remesh_edge_mm: 3"), std::string::npos);
  EXPECT_NE(Slurp(Path("out/curved_1.yaml")).find("rim_height_mm: 16"), std::string::npos);
  EXPECT_EQ(Slurp(Path("out/curved_1.yaml")).find("a0_mm"), std::string::npos);  // only the given one of the pair
}

TEST_F(PadRoundTrip, OtherShapesAndEveryOptionalField) {
  std::ofstream(Path("table.yaml"))
      << "schema_version: 1\nname: stepped\nkind: axisymmetric\nmass_kg: 1.25\nangular_segments: 48\n"
         "profile: {shape: table, radius_mm: 40, thickness_mm: 12, points_mm: [[0, 0], [25.5, 1.5], [40, 6]]}\n"
         "reference_point_mm: [0, 0, 10]\n"
         "inertia_kg_m2: {ixx: 0.0011, iyy: 0.0012, izz: 0.002, ixy: 0.00001}\n"
         "center_of_mass_mm: [0, 0, 5.5]\n";
  std::ofstream(Path("cap.yaml")) << "schema_version: 1\nkind: axisymmetric\nmass_kg: 0.9\n"
                                     "profile: {shape: spherical_cap, radius_mm: 30, thickness_mm: 10,"
                                     " sphere_radius_mm: 80, segments: 64}\n";
  std::ofstream(Path("cone.yaml")) << "schema_version: 1\nmass_kg: 0.7\n"
                                      "profile: {shape: cone, radius_mm: 30, thickness_mm: 20, half_angle_deg: 70}\n";
  std::ofstream(Path("expo.yaml")) << "schema_version: 1\nmass_kg: 1.1\n"
                                      "profile: {shape: exponential, radius_mm: 45, thickness_mm: 14, a0_mm: 3.5,"
                                      " a1_per_mm: 0.03}\n";
  for (const char* name : {"table", "cap", "cone", "expo"}) {
    SCOPED_TRACE(name);
    const PadSpec pad = LoadPad(Path(std::string(name) + ".yaml"));
    RoundTrip(pad, Path("out/" + std::string(name) + "_1.yaml"), Path("out/" + std::string(name) + "_2.yaml"));
  }
  const PadSpec table = LoadPad(Path("out/table_1.yaml"));
  ASSERT_TRUE(table.file.inertia_kg_m2.has_value());
  EXPECT_EQ((*table.file.inertia_kg_m2)[3], 0.00001);
  EXPECT_EQ(table.file.angular_segments, 48);
  EXPECT_EQ(table.file.points_mm.size(), 3u);
}

TEST_F(PadRoundTrip, MeshPadByDensity) {
  std::ofstream(Path("dense.yaml")) << "schema_version: 1\nname: dense_hex\nkind: mesh\ndensity_kg_m3: 2700\n"
                                       "mesh: {file: " << DataDirectory() << "/pads/meshes/hex_pad.stl, unit: mm}\n";
  const PadSpec pad = LoadPad(Path("dense.yaml"));
  EXPECT_GT(pad.mass_kg, 0.0);
  RoundTrip(pad, Path("out/dense_1.yaml"), Path("out/dense_2.yaml"));
  EXPECT_NE(Slurp(Path("out/dense_1.yaml")).find("density_kg_m3: 2700"), std::string::npos);
}

}  // namespace
}  // namespace touchdown::io
