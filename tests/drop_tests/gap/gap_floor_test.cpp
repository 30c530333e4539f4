// The floor read from the replicates (drop_tests/gap/gap_floor.h) on residuals made by hand: each
// drop's residual is its condition's common part (what the model misses) plus its own part
// (scatter), so the pure error is the own parts' variance about their condition's mean, known in
// closed form, and the lack of fit the common parts'.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "drop_tests/gap/diagnose.h"
#include "drop_tests/gap/gap_floor.h"

namespace touchdown::gap {
namespace {

constexpr size_t kSamples = 50;

// `conditions` speeds on one pad, soil and atmosphere, `replicates` drops each. Drop r of condition
// c has the residual common[c] + own * sign(r) * (-1)^i at sample i (own parts of opposite signs
// sum to zero over a pair), so with an even number of replicates the condition's mean is common[c]
// exactly and the pure error is own^2 R / (R - 1) per condition.
struct Case {
  FitProblem problem;
  std::vector<DropGap> gaps;
};

Case Make(int conditions, int replicates, double common, double own) {
  Case k;
  k.problem.pads.resize(1);
  k.problem.pads[0].name = "flat";
  k.problem.soils.resize(1);
  k.problem.soils[0].name = "fjs1_lp";
  for (int c = 0; c < conditions; ++c)
    for (int r = 0; r < replicates; ++r) {
      FitDrop d;
      d.speed_m_s = 0.8 + 0.2 * c;
      d.mass_kg = 1.6;
      d.gravity_m_s2 = 9.81;
      k.problem.drops.push_back(d);
      DropGap g;
      const double sign = r % 2 == 0 ? 1.0 : -1.0;
      for (size_t i = 0; i < kSamples; ++i)
        g.force_residual.push_back(common * (c + 1) + own * sign * (i % 2 == 0 ? 1.0 : -1.0));
      k.gaps.push_back(g);
    }
  return k;
}

TEST(GapFloor, ThePureErrorIsTheReplicatesScatterAboutTheirConditionsMean) {
  const double own = 0.01, noise_ms = 1e-6;
  const Case k = Make(3, 4, 0.02, own);
  const GapFloor f = ComputeFloor(k.problem, k.gaps, noise_ms);
  EXPECT_EQ(f.conditions, 3);
  EXPECT_EQ(f.replicate_df, 9);
  ASSERT_TRUE(f.from_replicates);
  // Per condition sum_d |r_d - mean|^2 / L = 4 own^2; pooled over 3 (R - 1) = 9 degrees of freedom.
  EXPECT_NEAR(f.replicate_ms, 3 * 4 * own * own / 9, 1e-15);
  EXPECT_EQ(f.ms, f.replicate_ms);
  // The common parts are not in it, however large.
  EXPECT_NEAR(ComputeFloor(Make(3, 4, 0.5, own).problem, Make(3, 4, 0.5, own).gaps, noise_ms).replicate_ms, f.replicate_ms,
              1e-15);
}

TEST(GapFloor, ItsUpperBoundIsThePureErrorsChiSquareBound) {
  const Case k = Make(3, 4, 0.02, 0.01);
  const GapFloor f = ComputeFloor(k.problem, k.gaps, 1e-6);
  // 9 degrees of freedom: ms 9 / chi2_0.05(9), the factor from SciPy (9 / chi2.ppf(0.05, 9)).
  EXPECT_NEAR(f.ms_upper / f.ms, 2.70667505879263, 1e-12);
  // A floor that is the sensor's noise (read from every rest sample) is its own bound.
  const GapFloor quiet = ComputeFloor(Make(3, 4, 0.02, 1e-4).problem, Make(3, 4, 0.02, 1e-4).gaps, 4e-4);
  EXPECT_EQ(quiet.ms_upper, quiet.ms);
}

TEST(GapFloor, ACandidateThatFitsTheReplicatesBetterLowersTheFloor) {
  // The base's residuals: the replicates differ by 0.01 each; a candidate's by 0.004 (its misfit,
  // shifted from replicate to replicate, no longer in them); another's by 0.02.
  const Case base = Make(3, 4, 0.02, 0.01), better = Make(3, 4, 0.0, 0.004), worse = Make(3, 4, 0.0, 0.02);
  GapFloor f = ComputeFloor(base.problem, base.gaps, 1e-6);
  ASSERT_TRUE(LowerFloorByCandidates(base.problem, {&worse.gaps, &better.gaps}, {"worse", "better"}, f));
  EXPECT_EQ(f.model, "better");
  EXPECT_NEAR(f.ms, 3 * 4 * 0.004 * 0.004 / 9, 1e-15);
  EXPECT_FALSE(LowerFloorByCandidates(base.problem, {&worse.gaps}, {"worse"}, f));
  // Never below the sensor's noise.
  GapFloor g = ComputeFloor(base.problem, base.gaps, 1e-4);
  ASSERT_TRUE(LowerFloorByCandidates(base.problem, {&better.gaps}, {"better"}, g));
  EXPECT_EQ(g.ms, 1e-4);
}

TEST(GapFloor, TooFewReplicatesOrAQuietStretchLeaveTheSensorsNoise) {
  const double noise_ms = 4e-4;
  const GapFloor few = ComputeFloor(Make(2, 2, 0.02, 0.01).problem, Make(2, 2, 0.02, 0.01).gaps, noise_ms);
  EXPECT_EQ(few.replicate_df, 2);
  EXPECT_FALSE(few.from_replicates);  // fewer than kMinPureErrorDf
  EXPECT_EQ(few.ms, noise_ms);
  const GapFloor quiet = ComputeFloor(Make(3, 4, 0.02, 1e-4).problem, Make(3, 4, 0.02, 1e-4).gaps, noise_ms);
  EXPECT_TRUE(quiet.from_replicates);
  EXPECT_LT(quiet.replicate_ms, noise_ms);
  EXPECT_EQ(quiet.ms, noise_ms);  // no model does better than the sensor
}

TEST(GapFloor, LackOfFitAgainstPureErrorIsTheClassicalFTest) {
  const double common = 0.02, own = 0.01;
  const Case k = Make(3, 4, common, own);
  const std::vector<CellLackOfFit> cells = LackOfFit(k.problem, k.gaps);
  ASSERT_EQ(cells.size(), 2u);  // the one cell, and "all"
  const CellLackOfFit& c = cells[0];
  EXPECT_EQ(c.conditions, 3);
  EXPECT_EQ(c.drops, 12);
  // Lack of fit: sum_c R |mean_c|^2 / C = 4 common^2 (1 + 4 + 9) / 3.
  EXPECT_NEAR(c.lack_of_fit_ms, 4 * common * common * 14 / 3, 1e-15);
  EXPECT_NEAR(c.pure_error_ms, 4 * own * own / 3, 1e-15);
  EXPECT_NEAR(c.F, c.lack_of_fit_ms / c.pure_error_ms, 1e-12);
  // F = 56 on (3, 9) degrees of freedom: p from SciPy's scipy.stats.f.sf(56, 3, 9).
  EXPECT_NEAR(c.p_value, 3.817336939663362e-06, 1e-12);
  EXPECT_EQ(cells[1].cell, "all");
  // Nothing common: F is 0 and p is 1.
  const std::vector<CellLackOfFit> none = LackOfFit(Make(3, 4, 0.0, own).problem, Make(3, 4, 0.0, own).gaps);
  EXPECT_EQ(none[0].F, 0.0);
  EXPECT_NEAR(none[0].p_value, 1.0, 1e-12);
}

}  // namespace
}  // namespace touchdown::gap
