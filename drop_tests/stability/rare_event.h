#pragma once
// Estimators of small failure probabilities P = P[g(U) <= 0] for a limit state g over standard-normal
// space (U ~ N(0, I_d)): plain Monte Carlo, subset simulation (Au & Beck 2001) and importance
// sampling around a design point (docs/stability_studies.md, "Rare-event estimators (the core)").
//
// g is evaluated in batches through the caller's function, so a study can run a batch of landings
// in parallel; the estimators themselves are sequential. Every random number is a counter-based
// draw (sweep::CounterUniform: splitmix64 keyed by seed, sample and stream, the family the sweep's
// samples come from) of the sample's own index, so the same seed gives bit-identical results
// whatever the batch function's threading and whatever the batch size.
//
// Inputs out of range throw std::invalid_argument at call; so does a batch function that returns
// a number of values other than the number of points, or a NaN (what a failed evaluation means,
// failure or not, is the caller's decision: it returns -inf or +inf).
#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "drop_tests/stability/study_statistics.h"

namespace touchdown::stability {

// g(u[i]) into g[i] for every point (the function resizes g to u.size()).
using LimitStateBatch = std::function<void(const std::vector<Eigen::VectorXd>& u, std::vector<double>& g)>;

// The counter-based draws every estimator (and a study's soil draws) takes its numbers from:
// sweep::CounterUniform's k 2^-53 moved to (k + 1/2) 2^-53, a uniform in the open interval (0, 1),
// so its standard normal quantile is always finite.
double OpenUniform(uint64_t seed, uint64_t sample, uint64_t stream);
double StandardNormal(uint64_t seed, uint64_t sample, uint64_t stream);

// What every estimate reports. `interval` is two-sided at the options' confidence; `cov` the
// estimate's coefficient of variation (standard error / P; +inf when P = 0); `evaluations` the
// calls of g spent (landings, later).
struct RareEventEstimate {
  double probability = 0.0;
  BinomialInterval interval;
  double cov = 0.0;
  int64_t evaluations = 0;
  // The failing point (g <= 0) of smallest |u| among those evaluated; empty when none failed.
  Eigen::VectorXd design_point;
};

// ---- Plain Monte Carlo --------------------------------------------------------------------
struct MonteCarloOptions {
  int64_t samples = 10000;  // >= 10
  uint64_t seed = 1;
  double confidence = 0.95;  // in (0, 1)
  int64_t batch = 1000;      // points per call of g, >= 1 (changes no result)
};
struct MonteCarloEstimate : RareEventEstimate {
  int64_t failures = 0;
};
// P = failures / N; the exact binomial (Clopper-Pearson) interval; CoV = sqrt((1 - P) / (N P)).
MonteCarloEstimate EstimateMonteCarlo(const LimitStateBatch& g, int dimension, const MonteCarloOptions& options);

// ---- Subset simulation --------------------------------------------------------------------
struct SubsetOptions {
  int64_t samples_per_level = 1000;  // N >= 10; N p0 must be a whole number of chains dividing N
  double p0 = 0.1;                   // the conditional probability of each intermediate level, (0, 0.5]
  // The modified Metropolis proposal: each component's candidate ~ N(x_j, spread^2), accepted
  // with probability min(1, phi(candidate) / phi(x_j)). > 0; 1 is Au & Beck's choice in
  // standard-normal space.
  double proposal_spread = 1.0;
  int max_levels = 30;  // >= 1: levels (the first one plain Monte Carlo included) before giving up
  uint64_t seed = 1;
  double confidence = 0.95;  // in (0, 1)
};
struct SubsetLevel {
  double threshold = 0.0;                // b_i: this level's failure region is g <= b_i (0 at the last)
  double conditional_probability = 0.0;  // p0 at intermediate levels, P_m at the last
  double gamma = 0.0;                    // the chains' correlation factor (0 at the first level)
  double cov = 0.0;                      // delta_i
  double acceptance_rate = 0.0;          // of the Metropolis candidates (0 at the first level)
  int64_t evaluations = 0;
};
struct SubsetEstimate : RareEventEstimate {
  std::vector<SubsetLevel> levels;
  // false when max_levels ran out (or the thresholds stopped falling) before the threshold reached
  // 0: then probability is p0^(levels - 1) times the last level's failing fraction (often 0) and
  // says little.
  bool reached_failure = false;
  // Au & Beck's bound for fully correlated levels, sum of delta_i (cov is theirs for uncorrelated
  // levels, sqrt(sum delta_i^2)): the interval is built on this one.
  double cov_upper = 0.0;
};
// P = p0^(m-1) P_m; CoV^2 = sum of the levels' delta_i^2 (Au & Beck 2001, eqs. 27-29):
// delta_1^2 = (1 - P_1) / (N P_1), delta_i^2 = (1 - P_i) / (N P_i) (1 + gamma_i) with gamma_i from
// the chains' indicator autocorrelation. The interval is lognormal with the CoV of fully
// correlated levels, cov_upper = sum of delta_i: the sum of squares leaves out the levels'
// correlation, and an interval on it covered the exact P in 90 % of 2,000 seeds at 95 % (99 % on
// cov_upper: conservative).
SubsetEstimate EstimateSubset(const LimitStateBatch& g, int dimension, const SubsetOptions& options);

// ---- Importance sampling ------------------------------------------------------------------
struct DesignPointRefinement {
  Eigen::VectorXd point;  // on the failing side of g = 0, within the final bracket
  int64_t evaluations = 0;
};
// The first crossing of g = 0 on the ray from the origin to `failing` (g(failing) <= 0): `rounds`
// batches of 7 points each cut the bracket [t_safe, t_fail] of t in t * failing by 8. Returns the
// failing end of the last bracket (so |point| <= |failing|); the origin when g(0) <= 0. rounds >= 1.
DesignPointRefinement RefineDesignPoint(const LimitStateBatch& g, const Eigen::VectorXd& failing, int rounds = 4);

struct ImportanceOptions {
  int64_t samples = 1000;  // >= 10
  uint64_t seed = 1;
  double confidence = 0.95;  // in (0, 1)
  int64_t batch = 1000;      // points per call of g, >= 1 (changes no result)
};
// Samples u ~ h = N(centre, I), weights w = phi(u) / h(u) = exp(|c|^2 / 2 - c.u):
// P = mean of 1[g <= 0] w, standard error from the weighted sample variance, and the normal
// interval P +- z SE (its low end floored at 0). `centre` is the design point (RefineDesignPoint
// of a subset run's EstimateSubset::design_point); any finite centre gives an unbiased estimate,
// one far from the most probable failure point a useless one.
RareEventEstimate EstimateImportance(const LimitStateBatch& g, const Eigen::VectorXd& centre,
                                     const ImportanceOptions& options);

}  // namespace touchdown::stability
