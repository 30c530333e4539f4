// Pads and soils from data/ and from user files; every bad input names file, field and value.
#include "drop_tests/catalog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "rft/input_error.h"

namespace touchdown::drop {
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
  EXPECT_EQ(lp.atmosphere, "vacuum");
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
        BadPadCase{"unknown kind", "kind: banana\nmass_kg: 1\nprofile: {shape: flat}\n", "kind: unknown pad kind"},
        BadPadCase{"schema", "schema_version: 7\nmass_kg: 1\nprofile: {shape: flat, radius_mm: 5, thickness_mm: 1}\n",
                   "unsupported version"}));

TEST_F(CatalogFiles, BadSoilsGiveOneClearError) {
  EXPECT_NE(SoilError("zeta_N_cm3: -2\n").find("zeta_N_cm3: must be positive"), std::string::npos);
  EXPECT_NE(SoilError("atmosphere: vacuum\n").find("zeta_N_cm3: missing"), std::string::npos);
  EXPECT_NE(SoilError("zeta_N_cm3: agarwal2023\n").find("needs bulk_density_kg_m3"), std::string::npos);
  EXPECT_NE(SoilError("zeta_N_cm3: 2\natmosphere: mars\n").find("atmosphere: must be 'vacuum' or 'air'"),
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

}  // namespace
}  // namespace touchdown::drop
