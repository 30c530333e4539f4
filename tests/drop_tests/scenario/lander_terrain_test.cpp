// A lander scenario's ground as a height field (ground.terrain, ground.craters): a flat raster or
// a crater field without craters lands bit-identically to level ground; a tilted raster lands as
// the same slope does; the refusals are one line naming the scenario, the block and the reason;
// the resolved copy reads back.
#include "drop_tests/scenario/lander_terrain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "drop_tests/scenario/lander_outputs.h"
#include "drop_tests/scenario/lander_setup.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::scenario {
namespace {

// n x n nodes, cellsize c, lower-left centre (x0, y0), heights h(x, y).
template <class Fn>
std::string AscText(int n, double c, double x0, double y0, Fn h) {
  char line[160];
  std::snprintf(line, sizeof line, "ncols %d\nnrows %d\nxllcenter %.17g\nyllcenter %.17g\ncellsize %.17g\n", n, n, x0,
                y0, c);
  std::string text = line;
  for (int r = 0; r < n; ++r) {
    for (int i = 0; i < n; ++i) {
      std::snprintf(line, sizeof line, "%s%.17g", i ? " " : "", h(x0 + i * c, y0 + (n - 1 - r) * c));
      text += line;
    }
    text += "\n";
  }
  return text;
}

// Case A's lander dropped 5 cm, for 0.4 s, with `ground_extra` lines in its ground block.
std::string ScenarioText(const std::string& ground_extra) {
  return "schema_version: 1\ntype: lander\nname: terrain_case\nlander: sutoh2017_lander\ngravity_m_s2: 9.81\n"
         "ground:\n  soil: fjs1_lp\n" +
         ground_extra + "initial:\n  drop_height_m: 0.05\nsimulation:\n  duration_s: 0.4\n  sample_rate_hz: 200\n";
}

class LanderTerrainTest : public testing_scratch::ScratchDirTest {
 protected:
  LanderRun Run(const std::string& name, const std::string& ground_extra) {
    LanderScenario s = LoadLanderScenario(Write(name + ".yaml", ScenarioText(ground_extra)));
    test::CoarsenPad(s);
    return RunLanderScenario(s);
  }
  // The message of the InputError loading the scenario gives, after the scenario's path.
  std::string Refusal(const std::string& ground_extra) {
    const std::string path = Write("refused.yaml", ScenarioText(ground_extra));
    try {
      LoadLanderScenario(path);
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
      return m.substr(path.size() + 2);
    }
    return "";
  }
};

// The summary's numbers, without the lines naming the scenario's file.
std::string Numbers(const LanderRun& run) {
  nlohmann::json j = LanderSummaryJson(run);
  j.erase("source");
  j.erase("scenario");
  return j.dump();
}

// A flat raster (at 2.5 m, shifted to height_m = 0 at the origin) and a crater field with no
// craters are flat height fields: rft::HeightFieldGround reports itself an exact plane and the
// contact takes the plane's path, so the landing is the level ground's to the last bit.
TEST_F(LanderTerrainTest, FlatHeightFieldLandsBitIdenticallyToLevelGround) {
  Write("flat.asc", AscText(41, 0.05, -1.0, -1.0, [](double, double) { return 2.5; }));
  const LanderRun level = Run("level", "");
  const LanderRun raster = Run("raster", "  terrain: {file: flat.asc}\n");
  const LanderRun no_craters =
      Run("craters",
          "  craters: {cumulative_per_m2: 0, min_diameter_m: 0.1, max_diameter_m: 0.5, seed: 3,"
          " cell_size_m: 0.05, half_extent_m: 1.0}\n");
  ASSERT_GT(level.result.trace.size(), 10u);
  ASSERT_GT(level.result.final_penetration_m[0], 0.0);
  for (const LanderRun* run : {&raster, &no_craters}) {
    EXPECT_EQ(Numbers(*run), Numbers(level));
    ASSERT_EQ(run->result.trace.size(), level.result.trace.size());
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(run->result.final_penetration_m[i], level.result.final_penetration_m[i]);
      EXPECT_EQ(run->result.peak_pad_force_N[i], level.result.peak_pad_force_N[i]);
    }
    EXPECT_EQ(run->result.dissipated_J, level.result.dissipated_J);
  }
}

// The same 8 deg slope as slope_deg and as a raster: the raster's height field takes the general
// contact path (per-vertex heights, no plane shortcut), which agrees with the plane's to rounding
// at every evaluation (tests/rft/height_field_ground_test.cpp: 2e-16 of the force measured). Over
// a landing the solver takes other steps (on a surface that is no plane the Newton Jacobian's x and
// y columns are differenced on their own instead of derived from the z column,
// lander/multibody/lander_jacobian.cpp), so the two agree to the integration's tolerance, not bit
// for bit: measured 4e-8 m in the penetrations (7 to 18 mm) and 3e-8 rad in the tilt; the bounds
// are 1 um and 1e-6 rad.
TEST_F(LanderTerrainTest, TiltedRasterLandsAsTheSameSlope) {
  const double t = std::tan(8.0 * M_PI / 180.0);
  Write("tilted.asc", AscText(41, 0.05, -1.0, -1.0, [&](double x, double) { return -t * x; }));
  const LanderRun slope = Run("slope", "  slope_deg: 8\n");
  const LanderRun raster = Run("raster", "  terrain: {file: tilted.asc, origin_m: [0, 0]}\n");
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(raster.result.final_penetration_m[i], slope.result.final_penetration_m[i], 1e-6) << "pad " << i + 1;
    EXPECT_GT(slope.result.final_penetration_m[i], 1e-3);
  }
  EXPECT_NEAR(raster.result.max_tilt_rad, slope.result.max_tilt_rad, 1e-6);
}

TEST_F(LanderTerrainTest, RefusalsNameTheScenarioTheBlockAndTheReason) {
  Write("flat.asc", AscText(41, 0.05, -1.0, -1.0, [](double, double) { return 0.0; }));
  Write("small.asc", AscText(5, 0.05, -0.1, -0.1, [](double, double) { return 0.0; }));
  Write("bad.asc", "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 five 6\n7 8 9\n");
  const std::string bad = Refusal("  terrain: {file: bad.asc}\n");
  EXPECT_NE(bad.find("ground.terrain: "), std::string::npos) << bad;
  EXPECT_NE(bad.find("bad.asc: line 7 (row 2, column 2): not a finite number: 'five'"), std::string::npos) << bad;
  EXPECT_EQ(Refusal("  slope_deg: 5\n  terrain: {file: flat.asc}\n"),
            "ground.slope_deg: only without a terrain file (the terrain gives the slopes)");
  EXPECT_EQ(Refusal("  terrain: {file: flat.asc, window_m: [0.5, 0, 0.2, 1]}\n"),
            "ground.terrain.window_m: must be [x_min, y_min, x_max, y_max] with x_min < x_max and y_min < y_max");
  EXPECT_EQ(Refusal("  craters: {cumulative_per_m2: 0.1, min_diameter_m: 0.1, max_diameter_m: 0.5, seed: 3}\n"),
            "ground.craters.cell_size_m: missing (the craters' grid without a terrain file)");
  EXPECT_EQ(Refusal("  craters: {cumulative_per_m2: 0.1, min_diameter_m: 0.5, max_diameter_m: 0.5, seed: 3,"
                    " cell_size_m: 0.05, half_extent_m: 1}\n"),
            "ground.craters.max_diameter_m: must be above min_diameter_m (0.5 m)");
  // A sweep or study setting slope_deg on a terrain scenario is refused when the landing is set up.
  LanderScenario swept = LoadLanderScenario(Write("swept.yaml", ScenarioText("  terrain: {file: flat.asc}\n")));
  swept.ground.slope_rad = 0.1;
  EXPECT_THROW(ResolveLander(swept), InputError);
  // The pads start outside a 20 cm raster: refused when the landing is set up.
  LanderScenario s = LoadLanderScenario(Write("small.yaml", ScenarioText("  terrain: {file: small.asc}\n")));
  try {
    ResolveLander(s);
    FAIL() << "the pads start off the terrain";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("ground.terrain: pad 1 starts at"), std::string::npos) << m;
    EXPECT_NE(m.find("widen the window or the extent"), std::string::npos) << m;
  }
}

// The craters of a seed are the same on every load, and the resolved copy (terrain file, window,
// origin and craters written back) reads back to the same ground.
TEST_F(LanderTerrainTest, CratersAreReproducibleAndTheResolvedCopyReadsBack) {
  Write("site.asc", AscText(61, 0.05, 10.0, 20.0, [](double x, double y) { return 0.02 * std::sin(x) * std::cos(y); }));
  const std::string ground =
      "  terrain: {file: site.asc, window_m: [10.2, 20.2, 12.8, 22.8], origin_m: [11.5, 21.4]}\n"
      "  craters: {cumulative_per_m2: 0.5, exponent: 2, min_diameter_m: 0.1, max_diameter_m: 0.6, degradation_min: 0,"
      " degradation_max: 0.5, seed: 42}\n";
  const LanderScenario a = LoadLanderScenario(Write("a.yaml", ScenarioText(ground)));
  const LanderScenario b = LoadLanderScenario(Path("a.yaml"));
  const rft::HeightGrid& ga = a.ground.height_field.surface->grid();
  EXPECT_EQ(ga.nx, 53);  // 10.2 .. 12.8 every 5 cm
  EXPECT_NEAR(ga.x0_m, 10.2 - 11.5, 1e-12);
  EXPECT_EQ(ga.heights_m, b.ground.height_field.surface->grid().heights_m);
  // Without the craters the raster's origin_m is the world origin, at height_m (0).
  const std::string terrain_only = ground.substr(0, ground.find("  craters"));
  const LanderScenario plain = LoadLanderScenario(Write("plain.yaml", ScenarioText(terrain_only)));
  EXPECT_NEAR(plain.ground.height_field.surface->Height(0.0, 0.0), 0.0, 1e-15);
  EXPECT_NEAR(plain.ground.height_field.surface->Height(0.3, -0.2),
              0.02 * (std::sin(11.8) * std::cos(21.2) - std::sin(11.5) * std::cos(21.4)), 1e-4);  // interpolated
  EXPECT_NE(plain.ground.height_field.surface->grid().heights_m, ga.heights_m);  // the craters changed it
  WriteResolvedLanderScenario(a, Path("resolved.yaml"), dir_.string());
  std::optional<lander::LanderSetup> setup;
  const LanderScenario back = LoadLanderScenarioWithSetup(Path("resolved.yaml"), setup);
  ASSERT_TRUE(back.ground.height_field.surface);
  EXPECT_EQ(back.ground.height_field.surface->grid().heights_m, ga.heights_m);
  EXPECT_EQ(back.ground.height_field.surface->grid().x0_m, ga.x0_m);
}

}  // namespace
}  // namespace touchdown::scenario
