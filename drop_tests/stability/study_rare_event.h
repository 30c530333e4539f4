#pragma once
// A stability study's tip-over probability by a rare-event estimator (`touchdown stability STUDY
// --method subset|importance`; docs/stability_studies.md, "Rare-event methods"):
//
//   The study's random variables are the coordinates of standard-normal space: component k of a
//   point u is random[k] drawn at the uniform Phi(u_k) (its inverse CDF: low + (high - low) Phi(u_k)
//   for a uniform, the choice's step function for a choice). The limit state is the landing's
//   tip-over margin (sweep::DropRecord::min_stability_margin_m, <= 0 exactly when it tipped over).
//   rare_event.h's estimators choose the points; each batch of them runs as landings of a plan
//   derived from the study's (SweepPlan::given_uniforms; its `variant` names the method, seed and
//   sizes) through the sweep engine, the k-th landing the estimator asks for under index k, into
//   DIR/<method>/results.sqlite. The points follow from the seed and the landings' results alone,
//   so results are bit-identical on any number of threads, MPI ranks or shards, and a killed run
//   resumes: the landings already in the database are read back, not run again. Shards run each
//   batch together and meet after it through files (rare_event_shards.h).
//
//   subset:     subset simulation (Au & Beck), `samples` landings per level, p0 = 0.1.
//   importance: the subset run as its first pass, its design point refined along its ray, then
//               `samples` landings drawn around it.
#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "rft/enum_names.h"
#include "drop_tests/stability/rare_event.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/sweep/sweep.h"

namespace touchdown::stability {

enum class StudyMethod { kMonteCarlo, kSubset, kImportance };
inline constexpr std::array<EnumName<StudyMethod>, 3> kStudyMethodNames{{{StudyMethod::kMonteCarlo, "monte_carlo"},
                                                                        {StudyMethod::kSubset, "subset"},
                                                                        {StudyMethod::kImportance, "importance"}}};
// "monte_carlo", "subset", "importance".
const char* StudyMethodName(StudyMethod m);
// The method `--method` names; InputError naming `field` (and the valid values) otherwise.
StudyMethod ParseStudyMethod(const std::string& text, const std::string& field = "--method");

// Landings per level (subset) and of the importance sample, when --samples does not say.
inline constexpr int64_t kDefaultRareEventSamples = 1000;
inline constexpr double kSubsetP0 = 0.1;
inline constexpr int kSubsetMaxLevels = 20;
inline constexpr int kDesignPointRounds = 4;

// Why the study cannot be estimated by `method` (a grid, a per-pad soil choice, no random
// variable, or a sample count that is no whole number of chains): InputError naming --method or
// --samples. Called at load time, before anything runs.
void RequireRareEventStudy(const Study& study, StudyMethod method, int64_t samples);

// The landings' plan for points of standard-normal space: `first` onward take `u` (dimension: the
// study's random variables). Its size is the estimator's budget, its variant names the run.
sweep::SweepPlan RareEventPlan(const Study& study, StudyMethod method, int64_t samples, int64_t first,
                               const std::vector<Eigen::VectorXd>& u);

// A point of standard-normal space as the study's variables, in file units (deg, m/s, ...; a pad
// or soil by name): {"slope_deg": 12.3, ...}.
nlohmann::json StudyVariablesJson(const Study& study, const Eigen::VectorXd& u);

// A landing's limit-state value: its margin, with the outcome deciding the side when the two
// disagree (tipped: at most 0; stayed up: above 0); +inf for a failed landing (counted as not
// tipped over, and reported).
double LimitStateOfLanding(const sweep::DropRecord& r);

struct RareEventDesignPoint {
  Eigen::VectorXd u;
  double beta = 0.0;  // |u|: the reliability index of the point
  std::string drop_id;  // the landing in DIR/<run>/
  std::string run;      // "subset" or "importance": the pass, and its folder, that ran it
};

struct RareEventStudyResult {
  StudyMethod method = StudyMethod::kSubset;
  int64_t samples = 0;  // per level / of the importance sample
  RareEventEstimate estimate;  // the method's
  std::optional<SubsetEstimate> subset;  // the subset run (the importance method's first pass)
  std::optional<Eigen::VectorXd> importance_centre;
  int64_t landings = 0;  // spent, all passes
  int64_t failed = 0;    // of them, failed (counted as not tipped over)
  int64_t margin_disagreements = 0;  // landings whose margin's sign disagrees with their outcome
  std::vector<RareEventDesignPoint> design_points;  // the failing landings of smallest |u|, at most 5
  // The subset run's first level: plain Monte Carlo draws of the study's own distribution, the
  // records the usual percentiles, map and worst cases describe (index k of `first_level_plan`).
  sweep::SweepPlan first_level_plan;
  std::vector<sweep::DropRecord> first_level;
  int stop_signal = 0;  // stopped by it: no estimate
  int64_t computed = 0, already_done = 0;
};

// Runs the estimator on the study's landings (`options`' threads, progress, stop flag and shard; an
// index list in them is ignored). Both methods run the subset pass into DIR/subset/ (the same
// landings, so one method's run resumes the other's); importance sampling then refines the design
// point and runs its sample into DIR/importance/. Shard I/N of N > 1 runs its share of each batch
// into DIR/shard_I_of_N/<pass>/ and waits for the others' after it; once done, shard 0 stores the
// whole run's landings in DIR/<pass>/ as one process would. `say`, when given, gets a line per
// pass (and a shard's long waits).
RareEventStudyResult RunRareEventStudy(const Study& study, StudyMethod method, int64_t samples,
                                       const std::string& out_dir, const sweep::SweepRunOptions& options,
                                       std::ostream* say = nullptr);

// summary.json's "rare_event" entry.
nlohmann::json RareEventJson(const Study& study, const RareEventStudyResult& r);

// The analysis of a finished run (not stopped) into DIR: WriteStudyAnalysis over its first level's
// landings (no follow-ups: "not run with a rare-event method"), summary.json carrying the method,
// its estimate and interval, and RareEventJson. The CLI and the Python module both write it here.
struct StudySummary;
StudySummary WriteRareEventAnalysis(const Study& study, const RareEventStudyResult& r, const std::string& out_dir);

}  // namespace touchdown::stability
