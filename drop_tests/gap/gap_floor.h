#pragma once
// The floor a model's gap is judged against (docs/model_gap.md, "The floor comes from the data").
// Where conditions repeat (pad, soil, atmosphere, speed, mass, gravity: diagnose_fit.h
// ConditionKey), the replicates' force residuals differ by what no model of the conditions can
// explain - the sensor's noise and the scatter between drops that their nuisances leave - while
// what the model misses is common to them. Their pure error (the mean square of each replicate's
// residual about its condition's mean residual) is that floor, in the held-out gap's units (a
// force NRMSE squared). Without replicates, the sensor's noise read at rest is the floor.
//
// The classical lack-of-fit test per (pad, soil, atmosphere) cell compares the conditions' mean
// residuals (lack of fit) with the pure error: F = (sum_c R_c |mean_c|^2 / L) / C over
// (sum_c sum_d |r_d - mean_c|^2 / L) / sum_c (R_c - 1), L the samples compared. Each drop's record
// counts as one observation (its samples are correlated), so the F test's degrees of freedom are
// counted in drops: C and sum (R_c - 1).
#include <limits>
#include <string>
#include <vector>

#include "drop_tests/gap/diagnose_fit.h"

namespace touchdown::gap {

struct DropGap;  // diagnose.h

struct GapFloor {
  double noise_ms = 0.0;   // the sensor's noise at rest: the held-out drops' mean noise NRMSE squared
  double replicate_ms = std::numeric_limits<double>::quiet_NaN();  // pure error (NaN: no replicates)
  int replicate_df = 0;    // sum over conditions of (replicates - 1)
  int conditions = 0;      // conditions with two or more drops
  double ms = 0.0;         // the floor used
  // The floor's one-sided 95 % upper bound: from replicates, the pure error's chi-square bound on its
  // degrees of freedom (replicate_ms df / chi2_0.05(df): 1.9 ms at 18 df); else the noise itself.
  // A held-out gap at or below it is not told apart from the floor.
  double ms_upper = 0.0;
  bool from_replicates = false;
  // The model whose residuals the pure error was read from ("base", or the candidate that fits the
  // replicates best: LowerFloorByCandidates).
  std::string model = "base";
};

// A cell's (pad, soil, atmosphere) lack of fit against its replicates' pure error.
struct CellLackOfFit {
  std::string cell;          // "flat / fjs1_lp / vacuum"
  int conditions = 0, drops = 0;
  double lack_of_fit_ms = 0.0, pure_error_ms = 0.0, F = 0.0, p_value = 1.0;
};

// The fewest degrees of freedom of pure error the floor is read from: fewer, and the noise floor is
// used (a mean square over two replicates scatters by a factor of ten).
inline constexpr int kMinPureErrorDf = 4;

// The floor of `gaps` (every drop's, the base's: DropGap::force_residual), with the held-out noise.
GapFloor ComputeFloor(const FitProblem& problem, const std::vector<DropGap>& gaps, double held_out_noise_ms);
// A model's misfit, shifted from replicate to replicate by their touchdown times and speeds, counts
// as pure error: read from the base, whose misfit is the largest, the floor came out above the
// held-out gap the hidden effect's own model reached (independent blind sets, docs/model_gap.md).
// Read from each fitted candidate's residuals too, the floor is the lowest (never below the noise):
// the least inflated. True when a candidate lowered `floor`.
bool LowerFloorByCandidates(const FitProblem& problem, const std::vector<const std::vector<DropGap>*>& candidate_gaps,
                            const std::vector<std::string>& names, GapFloor& floor);
// Per cell, for the cells with replicates; and the pooled test over all of them (cell "all").
std::vector<CellLackOfFit> LackOfFit(const FitProblem& problem, const std::vector<DropGap>& gaps);

}  // namespace touchdown::gap
