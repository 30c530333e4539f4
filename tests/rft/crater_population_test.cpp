// DrawCraters and AddCraters: a seed gives the same craters bit for bit; counts and sizes follow
// the cumulative size-frequency distribution; a crater's heights land on the grid's nodes.
#include "rft/crater_population.h"

#include <gtest/gtest.h>

#include <cmath>

#include "rft/crater_profile.h"

namespace touchdown::rft {
namespace {

CraterPopulationSpec Spec(uint64_t seed) {
  return {.cumulative_per_m2 = 0.079,
          .exponent = 2.0,
          .min_diameter_m = 1.0,
          .max_diameter_m = 8.0,
          .degradation_min = 0.0,
          .degradation_max = 0.6,
          .seed = seed};
}

TEST(RftCraterPopulation, SameSeedSameCratersBitForBit) {
  const auto a = DrawCraters(Spec(7), 0, 0, 50, 40), b = DrawCraters(Spec(7), 0, 0, 50, 40);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x_m, b[i].x_m);
    EXPECT_EQ(a[i].y_m, b[i].y_m);
    EXPECT_EQ(a[i].diameter_m, b[i].diameter_m);
    EXPECT_EQ(a[i].degradation, b[i].degradation);
  }
  const auto c = DrawCraters(Spec(8), 0, 0, 50, 40);
  EXPECT_NE(c.front().x_m, a.front().x_m);
}

// Over 66 x 56 m (the 50 x 40 m window widened by D_max = 8 m): 0.079 (1 - 1/64) 3696 = 287.4
// expected craters; the count is that rounded up or down. The fraction with D > 2 m is
// (2^-2 - 8^-2) / (1 - 8^-2) = 0.1905 for the truncated law; over 40 seeds (about 11,500 craters)
// its standard error is 0.0037, so 0.012 is more than three of them.
TEST(RftCraterPopulation, CountsAndSizesFollowTheDistribution) {
  const double expected = 0.079 * (1.0 - 1.0 / 64.0) * 66.0 * 56.0;
  long total = 0, above_2m = 0;
  for (uint64_t seed = 0; seed < 40; ++seed) {
    const auto craters = DrawCraters(Spec(seed), 0, 0, 50, 40);
    EXPECT_LE(std::abs(double(craters.size()) - expected), 1.0) << seed;
    for (const Crater& c : craters) {
      EXPECT_GE(c.diameter_m, 1.0);
      EXPECT_LE(c.diameter_m, 8.0);
      EXPECT_GE(c.degradation, 0.0);
      EXPECT_LT(c.degradation, 0.6);
      EXPECT_GE(c.x_m, -8.0);
      EXPECT_LE(c.x_m, 58.0);
      above_2m += c.diameter_m > 2.0;
    }
    total += static_cast<long>(craters.size());
  }
  EXPECT_NEAR(double(above_2m) / double(total), (0.25 - 1.0 / 64.0) / (1.0 - 1.0 / 64.0), 0.012);
}

TEST(RftCraterPopulation, CraterHeightsLandOnTheNodes) {
  HeightGrid g{
      .x0_m = 0.0, .y0_m = 0.0, .cell_m = 0.5, .nx = 81, .ny = 81, .heights_m = std::vector<double>(81 * 81, 1.0)};
  const Crater c{.x_m = 20.0, .y_m = 20.0, .diameter_m = 4.0, .degradation = 0.25};
  AddCraters({c}, &g);
  const CraterShape shape = DegradedCraterShape(0.25);
  EXPECT_EQ(g.At(40, 40), 1.0 + CraterHeight(shape, 4.0, 0.0));   // the centre node
  EXPECT_EQ(g.At(44, 40), 1.0 + CraterHeight(shape, 4.0, 2.0));   // on the rim
  EXPECT_EQ(g.At(48, 40), 1.0 + CraterHeight(shape, 4.0, 4.0));   // ejecta, two radii out
  EXPECT_EQ(g.At(40, 72), 1.0 + CraterHeight(shape, 4.0, 16.0));  // at the reach, 8 radii
  EXPECT_EQ(g.At(40, 73), 1.0);                                   // beyond it: untouched
  EXPECT_EQ(g.At(0, 0), 1.0);
}

TEST(RftCraterPopulation, RefusesWhatItCannotDraw) {
  EXPECT_EQ(CraterPopulationProblem(Spec(1), 2000.0), "");
  CraterPopulationSpec s = Spec(1);
  s.min_diameter_m = 9.0;
  EXPECT_EQ(CraterPopulationProblem(s, 2000.0), "diameters must satisfy 0 < min < max");
  s = Spec(1);
  s.degradation_max = 1.0;
  EXPECT_EQ(CraterPopulationProblem(s, 2000.0), "degradations must satisfy 0 <= min <= max < 1");
  s = Spec(1);
  s.min_diameter_m = 1e-3;
  EXPECT_NE(CraterPopulationProblem(s, 1e6).find("more than 1000000"), std::string::npos);
}

}  // namespace
}  // namespace touchdown::rft
