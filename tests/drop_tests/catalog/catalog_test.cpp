// Pads and soils from data/ and from user files; every bad input names file, field and value.
#include "drop_tests/catalog/catalog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "rft/input_error.h"

namespace touchdown::io {
namespace {

namespace fs = std::filesystem;

class CatalogFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_catalog_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // The message of the InputError that loading `text` as a pad (or soil) raises.
  std::string PadError(const std::string& text) {
    const std::string path = Write("pad.yaml", text);
    try {
      LoadPad(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  std::string SoilError(const std::string& text) {
    const std::string path = Write("soil.yaml", text);
    try {
      LoadSoil(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

TEST_F(CatalogFiles, BundledPadsAreThePapers) {
  for (const char* name : {"flat", "c4", "curved"}) {
    const PadSpec pad = LoadPad(name);
    EXPECT_EQ(pad.name, name);
    EXPECT_DOUBLE_EQ(pad.mass_kg, 1.6);
    EXPECT_NEAR(pad.profile.radius_m(), 0.05, 1e-12);
    EXPECT_NEAR(pad.profile.thickness_m(), 0.016, 1e-12);
  }
}

TEST_F(CatalogFiles, BundledSoilsDeriveZetaFromAgarwalScaling) {
  const rft::SoilParameters lp = LoadSoil("fjs1_lp"), cp = LoadSoil("fjs1_cp");
  for (const rft::SoilParameters& s : {lp, cp}) {
    const double xi = rft::AgarwalScalingXi(s.bulk_density_kg_m3, s.reference_gravity_m_s2,
                                            std::tan(s.internal_friction_angle_rad));
    EXPECT_NEAR(s.zeta_N_m3, xi, 1e-9 * xi) << s.name;
  }
  // The values the data files document in their comments.
  EXPECT_NEAR(lp.zeta_N_m3 / 1e6, 3.48, 0.005);
  EXPECT_NEAR(cp.zeta_N_m3 / 1e6, 9.22, 0.005);
  EXPECT_GT(cp.zeta_N_m3, lp.zeta_N_m3);
  EXPECT_EQ(lp.atmosphere, rft::Atmosphere::kVacuum);
}

TEST_F(CatalogFiles, UnknownNamesListTheKnownOnes) {
  try {
    LoadPad("hexagonal");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown name 'hexagonal'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("flat"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LoadSoil("moon_dust"), InputError);
  EXPECT_THROW(LoadPad((dir_ / "missing.yaml").string()), InputError);
}

// A data directory that is not there (an unset or wrong TOUCHDOWN_DATA_DIR, an install whose
// executable cannot find its share/ folder) is named as such, not reported as a misspelt name with
// an empty list of known ones.
TEST_F(CatalogFiles, AMissingDataDirectoryIsNamedNotCalledAnUnknownName) {
  const char* saved = std::getenv("TOUCHDOWN_DATA_DIR");
  const std::string restore = saved ? saved : "";
  const std::string missing = (dir_ / "no_data").string();
  ::setenv("TOUCHDOWN_DATA_DIR", missing.c_str(), 1);
  std::string message = "(no error)";
  try {
    LoadPad("flat");
  } catch (const InputError& e) {
    message = e.what();
  }
  if (saved) ::setenv("TOUCHDOWN_DATA_DIR", restore.c_str(), 1); else ::unsetenv("TOUCHDOWN_DATA_DIR");
  EXPECT_NE(message.find(missing + "/pads"), std::string::npos) << message;
  EXPECT_NE(message.find("no such data directory"), std::string::npos) << message;
  EXPECT_NE(message.find("TOUCHDOWN_DATA_DIR"), std::string::npos) << message;
  EXPECT_EQ(message.find("known:"), std::string::npos) << message;
}

struct BadPadCase {
  const char* what;
  const char* yaml;
  const char* expected;  // a fragment of the message
};

class BadPads : public CatalogFiles, public ::testing::WithParamInterface<BadPadCase> {};

TEST_P(BadPads, GiveOneClearError) {
  const std::string message = PadError(GetParam().yaml);
  EXPECT_NE(message.find("pad.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << GetParam().what << ": " << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadPads,
    ::testing::Values(
        BadPadCase{"malformed", "mass_kg: [1.6\nprofile: {", "malformed YAML"},
        BadPadCase{"not a mapping", "- 1\n- 2\n", "top level must be a YAML mapping"},
        BadPadCase{"missing mass", "profile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n", "mass_kg: missing"},
        BadPadCase{"negative mass", "mass_kg: -1.6\nprofile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n",
                   "mass_kg: must be positive, got '-1.6'"},
        BadPadCase{"nan mass", "mass_kg: .nan\nprofile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n",
                   "mass_kg: must be finite"},
        BadPadCase{"text mass", "mass_kg: heavy\nprofile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n",
                   "mass_kg: must be a number, got 'heavy'"},
        BadPadCase{"zero radius", "mass_kg: 1\nprofile: {shape: flat, radius_mm: 0, thickness_mm: 16}\n",
                   "profile.radius_mm: must be positive, got '0'"},
        BadPadCase{"infinite thickness", "mass_kg: 1\nprofile: {shape: flat, radius_mm: 50, thickness_mm: .inf}\n",
                   "profile.thickness_mm: must be finite"},
        BadPadCase{"unknown shape", "mass_kg: 1\nprofile: {shape: star, radius_mm: 50, thickness_mm: 16}\n",
                   "profile.shape: unknown shape 'star'"},
        BadPadCase{"typo field", "mass_kg: 1\nmas_kg: 2\nprofile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n",
                   "mas_kg: unknown field"},
        BadPadCase{"chamfer too big",
                   "mass_kg: 1\nprofile: {shape: chamfer, radius_mm: 50, thickness_mm: 16, chamfer_mm: 60}\n",
                   "chamfer: must be smaller"},
        BadPadCase{"curve above thickness",
                   "mass_kg: 1\nprofile: {shape: exponential, radius_mm: 50, thickness_mm: 16, a0_mm: 5, "
                   "a1_per_mm: 0.1}\n",
                   "above the thickness"},
        BadPadCase{"decreasing table",
                   "mass_kg: 1\nprofile: {shape: table, radius_mm: 50, thickness_mm: 16, points_mm: [[0, 0], [30, "
                   "2], [20, 3], [50, 4]]}\n",
                   "never decrease"},
        BadPadCase{"bad table pair",
                   "mass_kg: 1\nprofile: {shape: table, radius_mm: 50, thickness_mm: 16, points_mm: [[0, 0], [50]]}\n",
                   "points_mm[1]: must be a pair"},
        // The pad fuzzer's find: a table without its points threw yaml-cpp's InvalidNode (exit 1).
        BadPadCase{"table without points", "mass_kg: 1\nprofile: {shape: table, radius_mm: 40, thickness_mm: 10,}\n",
                   "points_mm: must be a list"},
        BadPadCase{"unknown kind", "kind: banana\nmass_kg: 1\nprofile: {shape: flat}\n", "kind: unknown pad kind"},
        BadPadCase{"schema", "schema_version: 7\nmass_kg: 1\nprofile: {shape: flat, radius_mm: 5, thickness_mm: 1}\n",
                   "unsupported version"}));

TEST_F(CatalogFiles, BadSoilsGiveOneClearError) {
  EXPECT_NE(SoilError("zeta_N_cm3: -2\n").find("zeta_N_cm3: must be positive"), std::string::npos);
  EXPECT_NE(SoilError("atmosphere: vacuum\n").find("zeta_N_cm3: missing"), std::string::npos);
  EXPECT_NE(SoilError("zeta_N_cm3: agarwal2023\n").find("needs bulk_density_kg_m3"), std::string::npos);
  EXPECT_NE(SoilError("zeta_N_cm3: 2\natmosphere: mars\n").find("atmosphere: must be 'vacuum' or 'air'"),
            std::string::npos);
  EXPECT_NE(SoilError("zeta_N_cm3: 2\ngravity_scaling: linear\n")
                .find("gravity_scaling: must be 'lithostatic' or 'none', got 'linear'"),
            std::string::npos);
  EXPECT_NE(SoilError("zeta_N_cm3: 2\ninternal_friction_angle_deg: 95\n").find("below 90"), std::string::npos);
  EXPECT_EQ(SoilError("zeta_N_cm3: 2.5\natmosphere: air\n"), "(no error)");
}

TEST_F(CatalogFiles, TabulatedProfileFromUserFile) {
  const std::string path = Write("ring.yaml",
                                 "name: ring\nmass_kg: 2\nprofile: {shape: table, radius_mm: 40, thickness_mm: 10, "
                                 "points_mm: [[0, 0], [20, 0], [40, 5]]}\n");
  const PadSpec pad = LoadPad(path);
  EXPECT_EQ(pad.name, "ring");
  ASSERT_EQ(pad.profile.points.size(), 4u);  // + the side wall
  EXPECT_NEAR(pad.profile.points.back().u_m, 0.010, 1e-12);
}

// --- Pad bodies and mesh pads (kind: mesh) ---

// Sum of n dA over a closed surface: zero (divergence theorem).
double VectorAreaNorm(const rft::SurfaceElements& e) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < e.size(); ++i) sum += e.area_m2(i) * e.n_B.col(i);
  return sum.norm();
}

TEST_F(CatalogFiles, EveryBundledPadHasABody) {
  const double r = 0.05, h = 0.016, pi = std::acos(-1.0);
  for (const char* name : {"flat", "c4", "curved", "hex"}) {
    SCOPED_TRACE(name);
    const PadSpec pad = LoadPad(name);
    EXPECT_EQ(pad.is_axisymmetric(), std::string(name) != "hex");
    EXPECT_EQ(pad.kind, pad.is_axisymmetric() ? PadKind::kAxisymmetric : PadKind::kMesh);
    EXPECT_DOUBLE_EQ(pad.body.mass_kg, 1.6);
    EXPECT_DOUBLE_EQ(pad.mass_kg, 1.6);
    // Reference point at the top centre: the lowest point 16 mm below it, on the axis.
    EXPECT_NEAR(pad.body.lowest_z_B, -h, 1e-12);
    EXPECT_NEAR(pad.body.com_B.head<2>().norm(), 0.0, 1e-9);
    EXPECT_LT(pad.body.com_B.z(), 0.0);
    EXPECT_GT(pad.body.surface.size(), 1000);
    EXPECT_LT(VectorAreaNorm(pad.body.surface), 1e-12);
  }
  // The flat pad's revolved surface is the cylinder's, to the angular discretisation error.
  const PadSpec flat = LoadPad("flat");
  EXPECT_NEAR(flat.body.surface.area_m2.sum() / (2 * pi * r * r + 2 * pi * r * h), 1.0, 1e-3);
  EXPECT_NEAR(flat.body.com_B.z(), -h / 2, 1e-12);
  EXPECT_NEAR(flat.body.inertia_com_B(2, 2) / (1.6 * r * r / 2), 1.0, 1e-3);
  // The hexagonal prism: 2 hexagons of circumradius 50 mm and six 50 x 16 mm sides.
  const PadSpec hex = LoadPad("hex");
  EXPECT_TRUE(hex.profile.points.empty());
  EXPECT_NEAR(hex.body.surface.area_m2.sum(), 2 * 1.5 * std::sqrt(3.0) * r * r + 6 * r * h, 1e-9);
  EXPECT_NEAR(hex.body.com_B.z(), -h / 2, 1e-9);
}

TEST_F(CatalogFiles, AxisymmetricPadBodyOptions) {
  const PadSpec pad = LoadPad(Write("coarse.yaml",
                                    "mass_kg: 2\nangular_segments: 12\nreference_point_mm: [0, 0, 0]\n"
                                    "profile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n"));
  EXPECT_NEAR(pad.body.lowest_z_B, 0.0, 1e-15);
  EXPECT_NEAR(pad.body.com_B.z(), 0.008, 1e-12);
  const double hexagon_ring = 12;  // rim ring of 12: area of the inscribed 12-gon
  EXPECT_NEAR(pad.body.surface.area_m2.sum(),
              2 * 0.5 * hexagon_ring * 0.05 * 0.05 * std::sin(2 * std::acos(-1.0) / 12) +
                  12 * 2 * 0.05 * std::sin(std::acos(-1.0) / 12) * 0.016,
              1e-12);
}

TEST_F(CatalogFiles, ARevolvedPadAtOtherAngularSegmentsIsItsFileWithThatCount) {
  const std::string file = Write("pad.yaml",
                                 "mass_kg: 0.08\nangular_segments: 64\nreference_point_mm: [0, 0, 20]\n"
                                 "profile: {shape: flat, radius_mm: 27.5, thickness_mm: 10}\n");
  const PadSpec fine = LoadPad(file);
  const PadSpec coarse = PadWithAngularSegments(fine, 32);
  const PadSpec written = LoadPad(Write("coarse.yaml",
                                        "mass_kg: 0.08\nangular_segments: 32\nreference_point_mm: [0, 0, 20]\n"
                                        "profile: {shape: flat, radius_mm: 27.5, thickness_mm: 10}\n"));
  EXPECT_EQ(coarse.file.angular_segments, 32);
  EXPECT_EQ(coarse.source, fine.source);
  ASSERT_EQ(coarse.body.surface.size(), written.body.surface.size());
  EXPECT_LT(4 * coarse.body.surface.size(), fine.body.surface.size() + 100);  // rings scale with the rim too
  EXPECT_EQ(coarse.body.surface.p0_B, written.body.surface.p0_B);
  EXPECT_EQ(coarse.mass_kg, fine.mass_kg);
  EXPECT_EQ(coarse.body.lowest_z_B, fine.body.lowest_z_B);
  // Re-made from the resolved pad, not from its file: the file changed or gone changes nothing.
  std::filesystem::remove(file);
  const PadSpec again = PadWithAngularSegments(fine, 32);
  EXPECT_EQ(again.body.surface.p0_B, coarse.body.surface.p0_B);
  EXPECT_EQ(again.body.surface.area_m2, coarse.body.surface.area_m2);
  EXPECT_EQ(FlatPadWithRadius(fine, 20.0).file.radius_mm, 20.0);
  try {
    PadWithAngularSegments(fine, 3);
    ADD_FAILURE() << "3 segments accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("angular_segments: must be at least 6, got 3"), std::string::npos) << e.what();
  }
}

class MeshPads : public CatalogFiles {
 protected:
  void SetUp() override {
    CatalogFiles::SetUp();
    fs::create_directories(dir_ / "meshes");
    // A 100 x 100 x 20 mm box as quads (OFF), and the same box without its top.
    const std::string vertices = "0 0 0\n100 0 0\n100 100 0\n0 100 0\n0 0 20\n100 0 20\n100 100 20\n0 100 20\n";
    const std::string sides = "4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
    Write("meshes/box.off", "OFF\n8 6 0\n" + vertices + sides + "4 4 5 6 7\n");
    Write("meshes/open_box.off", "OFF\n8 5 0\n" + vertices + sides);
  }
};

TEST_F(MeshPads, MeshPadFromUserFile) {
  const PadSpec pad = LoadPad(Write("box.yaml",
                                    "name: box\nkind: mesh\nmesh: {file: meshes/box.off, unit: mm}\n"
                                    "density_kg_m3: 1000\n"));
  EXPECT_EQ(pad.name, "box");
  EXPECT_FALSE(pad.is_axisymmetric());
  EXPECT_EQ(pad.mesh_file, (dir_ / "meshes/box.off").lexically_normal().string());
  EXPECT_NEAR(pad.mass_kg, 0.2, 1e-12);  // 0.1 x 0.1 x 0.02 m^3 of 1000 kg/m^3
  // Default reference point: top centre of the bounding box.
  EXPECT_TRUE(pad.body.com_B.isApprox(Eigen::Vector3d(0, 0, -0.01), 1e-9));
  EXPECT_NEAR(pad.body.lowest_z_B, -0.02, 1e-15);
  EXPECT_NEAR(pad.body.inertia_com_B(2, 2), 0.2 * (0.01 + 0.01) / 12, 1e-12);
  EXPECT_EQ(pad.body.surface.size(), 12);

  const PadSpec given = LoadPad(Write("given.yaml",
                                      "kind: mesh\nmesh: {file: meshes/box.off, unit: mm, remesh_edge_mm: 10}\n"
                                      "mass_kg: 1.2\nreference_point_mm: [50, 50, 0]\n"
                                      "inertia_kg_m2: {ixx: 0.002, iyy: 0.002, izz: 0.003, ixy: -0.0001}\n"
                                      "center_of_mass_mm: [50, 50, 5]\n"));
  EXPECT_DOUBLE_EQ(given.mass_kg, 1.2);
  EXPECT_TRUE(given.body.com_B.isApprox(Eigen::Vector3d(0, 0, 0.005), 1e-12));
  EXPECT_DOUBLE_EQ(given.body.inertia_com_B(0, 1), -0.0001);
  EXPECT_DOUBLE_EQ(given.body.inertia_com_B(1, 0), -0.0001);
  EXPECT_GT(given.body.surface.size(), 12);  // remeshed
}

TEST_F(MeshPads, AMeshPadHasNoAngularSegmentsToChange) {
  const PadSpec pad = LoadPad(Write("box.yaml", "kind: mesh\nmesh: {file: meshes/box.off, unit: mm}\ndensity_kg_m3: 1000\n"));
  try {
    PadWithAngularSegments(pad, 32);
    ADD_FAILURE() << "a mesh pad re-meshed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("box.yaml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is a mesh"), std::string::npos) << e.what();
  }
}

TEST_F(MeshPads, BadMeshPadsGiveOneClearError) {
  const std::string head = "kind: mesh\n";
  const std::string good_mesh = "mesh: {file: meshes/box.off, unit: mm}\n";
  const struct {
    std::string yaml, expected;
  } cases[] = {
      {head + "mesh: {file: meshes/none.stl, unit: mm}\nmass_kg: 1\n",
       "pad.yaml: mesh.file: " + (dir_ / "meshes/none.stl").string() + ": mesh file not found"},
      {head + "mesh: {file: meshes/box.off, unit: inch}\nmass_kg: 1\n",
       "pad.yaml: mesh.unit: unknown length unit 'inch' (mm, m)"},
      {head + "mesh: {file: meshes/open_box.off, unit: mm}\nmass_kg: 1\n",
       "open_box.off: 4 border edges, mesh is not closed"},
      {head + good_mesh + "mass_kg: 1\ndensity_kg_m3: 1000\n", "mass_kg: give exactly one of mass_kg and density_kg_m3"},
      {head + good_mesh, "mass_kg: give exactly one of mass_kg and density_kg_m3"},
      {head + "mass_kg: 1\n", "mesh"},
      {head + "mesh: {file: meshes/box.off, unit: mm, scale: 2}\nmass_kg: 1\n", "mesh.scale: unknown field"},
      {head + good_mesh + "mass_kg: 1\nreference_point_mm: [0, 0]\n", "reference_point_mm: must be a list of three"},
      {head + good_mesh + "mass_kg: 1\ninertia_kg_m2: {ixx: 0.001, iyy: 0.001, izz: 0.003}\n",
       "inertia_kg_m2: is not a rigid body's inertia"},
      {head + good_mesh + "mass_kg: 1\ncenter_of_mass_mm: [0, 0, 0]\n", "center_of_mass_mm: needs inertia_kg_m2"},
      {head + good_mesh + "mass_kg: 1\nprofile: {shape: flat}\n", "profile: unknown field"},
      {"mass_kg: 1\nangular_segments: 3\nprofile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n",
       "angular_segments: must be at least 6, got 3"},
      {"kind: banana\nmass_kg: 1\n", "kind: unknown pad kind 'banana' (axisymmetric, mesh)"},
      // Resolution caps: a hand-written 1e9 is refused at load, not run out of memory.
      {"mass_kg: 1\nangular_segments: 1000000000\nprofile: {shape: flat, radius_mm: 50, thickness_mm: 16}\n",
       "angular_segments: must be at most 1024, got 1000000000"},
      {"mass_kg: 1\nprofile: {shape: spherical_cap, radius_mm: 50, thickness_mm: 16, sphere_radius_mm: 100, "
       "segments: 1000000000}\n",
       "profile.segments: must be at most 10000, got 1000000000"},
      {"mass_kg: 1\nprofile: {shape: table, radius_mm: 50, thickness_mm: 16, points_mm: [" + [] {
         std::string points;
         for (int i = 0; i <= 10001; ++i) points += (i ? ", [" : "[") + std::to_string(50.0 * i / 10001) + ", 0]";
         return points;
       }() + "]}\n",
       "profile.points_mm: must have at most 10001 points, got 10002"},
      {head + "mesh: {file: meshes/box.off, unit: mm, remesh_edge_mm: 0.000001}\nmass_kg: 1\n",
       "remesh edge length 1e-06 mm would make about"},
  };
  for (const auto& c : cases) {
    const std::string message = PadError(c.yaml);
    EXPECT_NE(message.find("pad.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.yaml << " -> " << message;
  }
}

// The input a command runs (campaign, lander, sweep, trade, stability) by path or bundled name.
TEST_F(CatalogFiles, ABundledInputRunsByItsName) {
  EXPECT_EQ(ResolveInputDocument(InputDocument::kLander, "lander_case_B"),
            DataDirectory() + "/scenarios/lander_case_B.yaml");
  EXPECT_EQ(ResolveInputDocument(InputDocument::kCampaign, "sutoh2017_single_footpad"),
            DataDirectory() + "/scenarios/sutoh2017_single_footpad.yaml");
  EXPECT_EQ(ResolveInputDocument(InputDocument::kStudy, "lunar_paper_lander"),
            DataDirectory() + "/studies/lunar_paper_lander.yaml");
  // sweep runs studies too (a study is a lander sweep); trade only sweeps.
  EXPECT_EQ(ResolveInputDocument(InputDocument::kSweep, "lunar_paper_lander"),
            DataDirectory() + "/studies/lunar_paper_lander.yaml");
  EXPECT_THROW(ResolveInputDocument(InputDocument::kTrade, "lunar_paper_lander"), InputError);
  // What reads as a path stays one: its loader says what is wrong with it.
  EXPECT_EQ(ResolveInputDocument(InputDocument::kLander, "lander_case_B.yaml"), "lander_case_B.yaml");
  EXPECT_EQ(ResolveInputDocument(InputDocument::kLander, "cases/lander_case_B"), "cases/lander_case_B");
}

TEST_F(CatalogFiles, AFileOfTheNameInTheWorkingDirectoryComesFirst) {
  const fs::path here = fs::current_path();
  fs::current_path(dir_);
  Write("lander_case_B", "mine");
  const std::string resolved = ResolveInputDocument(InputDocument::kLander, "lander_case_B");
  fs::current_path(here);
  EXPECT_EQ(resolved, "lander_case_B");
}

TEST_F(CatalogFiles, AShelfHoldsOnlyItsType) {
  // data/studies holds the studies and the lander scenarios they start from.
  const std::vector<CatalogShelf> studies = ShelvesOf(InputDocument::kStudy);
  ASSERT_EQ(studies.size(), 1u);
  EXPECT_EQ(ShelfNames(studies[0]),
            (std::vector<std::string>{"lab_paper_lander", "lab_rare_event_agreement", "lunar_paper_lander",
                                      "lunar_paper_lander_calibrated", "lunar_paper_lander_calibrated_lambda",
                                      "lunar_paper_lander_soil_lambda", "lunar_paper_lander_soil_uncertainty",
                                      "lunar_patchy_ground", "lunar_rare_tip_over"}));
  const std::vector<CatalogShelf> landers = ShelvesOf(InputDocument::kLander);
  ASSERT_EQ(landers.size(), 1u);
  EXPECT_EQ(ShelfNames(landers[0]),
            (std::vector<std::string>{"lander_case_A", "lander_case_B", "lander_case_C", "lander_lunar_bekker"}));
  try {
    ResolveInputDocument(InputDocument::kStudy, "lunar_paper_lander_scenario");
    FAIL() << "a lander scenario is not a study";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("lunar_paper_lander_scenario: no such file, nor a bundled name (did you mean "
                           "'lunar_paper_lander'?)"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("studies in " + DataDirectory() + "/studies: lab_paper_lander, lab_rare_event_agreement, "
                           "lunar_paper_lander, lunar_paper_lander_calibrated, lunar_paper_lander_calibrated_lambda, "
                           "lunar_paper_lander_soil_lambda, lunar_paper_lander_soil_uncertainty, "
                           "lunar_patchy_ground, lunar_rare_tip_over)"),
              std::string::npos)
        << message;
  }
}

TEST_F(CatalogFiles, EveryListedNameResolvesToAFileOfItsShelf) {
  for (InputDocument d : {InputDocument::kCampaign, InputDocument::kLander, InputDocument::kSweep,
                          InputDocument::kTrade, InputDocument::kStudy})
    for (const CatalogShelf& shelf : ShelvesOf(d)) {
      const std::vector<std::string> names = ShelfNames(shelf);
      EXPECT_FALSE(names.empty()) << shelf.label;
      for (const std::string& name : names) {
        const std::string file = ResolveInputDocument(d, name);
        EXPECT_TRUE(fs::is_regular_file(file)) << file;
        EXPECT_EQ(fs::path(file).parent_path().filename(), shelf.kind) << file;
      }
    }
}

}  // namespace
}  // namespace touchdown::io
