// The random soil-patch field: its cells tile the square they promise, each soil turns up with its
// probability, the same seed gives the same field, and a lander on it stands on the soils its
// cells hold; a per-landing seed is refused outside a study.
#include "drop_tests/scenario/soil_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "drop_tests/scenario/lander_setup.h"
#include "rft/soil_map.h"
#include "rft/input_error.h"
#include "tests/drop_tests/scenario/lander_test_support.h"

namespace touchdown::scenario {
namespace {

SoilFieldSpec TwoSoilField(double p_second, uint64_t seed) {
  SoilFieldSpec f;
  f.soils = {"fjs1_lp", "fjs1_cp"};
  f.probabilities = {1.0 - p_second, p_second};
  f.cell_size_m = 0.1;
  f.half_extent_m = 1.0;
  f.seed = seed;
  return f;
}

TEST(SoilField, CellsTileTheSquareAroundTheCentreShiftedByLessThanACell) {
  const std::vector<SoilFieldCell> cells = DrawSoilField(TwoSoilField(0.5, 3), 0.2, -0.4);
  ASSERT_EQ(cells.size(), 21u * 21u);  // ceil(2 / 0.1) + 1 cells a side
  const double x0 = cells.front().x0, y0 = cells.front().y0;
  EXPECT_GT(x0, 0.2 - 1.0 - 0.1);
  EXPECT_LE(x0, 0.2 - 1.0);
  EXPECT_GT(y0, -0.4 - 1.0 - 0.1);
  EXPECT_LE(y0, -0.4 - 1.0);
  EXPECT_GE(cells.back().x1, 0.2 + 1.0);  // the square is covered
  EXPECT_GE(cells.back().y1, -0.4 + 1.0);
  for (size_t k = 1; k < 21; ++k) EXPECT_NEAR(cells[k].x0 - cells[k - 1].x0, 0.1, 1e-12);
}

TEST(SoilField, EachSoilTurnsUpWithItsProbabilityAndTheSeedFixesTheField) {
  SoilFieldSpec f = TwoSoilField(0.3, 11);
  f.half_extent_m = 10.0;  // 201 x 201 cells
  const std::vector<SoilFieldCell> cells = DrawSoilField(f, 0.0, 0.0);
  double second = 0.0;
  for (const SoilFieldCell& c : cells) second += c.soil == 1;
  const double n = static_cast<double>(cells.size()), p = 0.3;
  // Binomial: within 5 standard deviations of n p.
  EXPECT_NEAR(second, n * p, 5.0 * std::sqrt(n * p * (1.0 - p)));
  const std::vector<SoilFieldCell> again = DrawSoilField(f, 0.0, 0.0);
  ASSERT_EQ(again.size(), cells.size());
  for (size_t k = 0; k < cells.size(); ++k) ASSERT_EQ(again[k].soil, cells[k].soil) << k;
  f.seed = 12;
  const std::vector<SoilFieldCell> other = DrawSoilField(f, 0.0, 0.0);
  int differ = 0;
  for (size_t k = 0; k < cells.size(); ++k) differ += other[k].soil != cells[k].soil;
  EXPECT_GT(differ, static_cast<int>(0.3 * n));  // another seed: another field (2 p (1 - p) = 42 % of cells)
  for (double certain : {0.0, 1.0})
    for (const SoilFieldCell& c : DrawSoilField(TwoSoilField(certain, 5), 0.0, 0.0)) ASSERT_EQ(c.soil, certain == 1.0 ? 1 : 0);
}

TEST(SoilField, PerLandingSeedsDifferBetweenLandingsAndRepeatForOne) {
  EXPECT_EQ(PerLandingFieldSeed(2017, 5), PerLandingFieldSeed(2017, 5));
  EXPECT_NE(PerLandingFieldSeed(2017, 5), PerLandingFieldSeed(2017, 6));
  EXPECT_NE(PerLandingFieldSeed(2017, 5), PerLandingFieldSeed(2018, 5));
}

TEST(SoilFieldLander, AllClosePackedCellsPutEveryPadOnIt) {
  LanderScenario s = test::CoarseScenario("lander_case_A");
  s.ground.soil_field = TwoSoilField(1.0, 1);
  s.options.duration_s = 0.3;
  const LanderRun run = RunLanderScenario(s);
  for (const std::string& soil : run.soil_under_pad) EXPECT_EQ(soil, "fjs1_cp");
  s.ground.soil_field->seed_per_landing = true;
  EXPECT_THROW(RunLanderScenario(s), InputError);
}

}  // namespace
}  // namespace touchdown::scenario

namespace touchdown::rft {
namespace {

// The grid a field is looked up through: the cell holding a point, -1 outside, patches first.
TEST(SoilGridLookup, FindsTheCellOrNoneAndPatchesComeFirst) {
  Terrain t;
  t.grid.x0_m = -1.0;
  t.grid.y0_m = 2.0;
  t.grid.cell_m = 0.5;
  t.grid.nx = 3;
  t.grid.ny = 2;
  t.grid.soil = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(t.grid.SoilAt(-0.9, 2.1), 0);
  EXPECT_EQ(t.grid.SoilAt(-0.4, 2.1), 1);  // i = 1
  EXPECT_EQ(t.grid.SoilAt(0.4, 2.9), 5);   // i = 2, j = 1
  EXPECT_EQ(t.grid.SoilAt(0.6, 2.1), -1);  // right of the grid
  EXPECT_EQ(t.grid.SoilAt(-0.9, 1.9), -1);  // below it
  EXPECT_EQ(t.SoilAt(0.6, 2.1), 0);        // outside: the default soil
  EXPECT_EQ(t.SoilAt(0.4, 2.9), 5);
  t.patches.push_back({"first", RectanglePolygon(0.0, 2.5, 1.0, 3.5), 7});
  EXPECT_EQ(t.SoilAt(0.4, 2.9), 7);
}

}  // namespace
}  // namespace touchdown::rft
