#pragma once
// `touchdown diagnose MEASURED_DIR [--model MODEL.yaml] --out DIR`: where simulation and
// measurement disagree, which library effect (drop_tests/model/effects.h) is missing, and how much
// of the gap it closes. Documented in docs/model_gap.md.
//
//  1. Split: within each (pad, soil, atmosphere) cell, drops ordered by impact speed then id;
//     every third one starting with the second (ranks 1, 4, 7, ...) is held out, the rest train.
//     Deterministic, and every cell and soil keeps training drops. Or (--fit-on) the drops the
//     user designates train and every other drop is held out: each model is fitted on those cases
//     and predicts the rest.
//     Calibrate zeta per soil on the training drops (diagnose_fit.h), simulate every drop.
//  2. Gap per drop and overall on held-out drops (compare.h metrics), and where it
//     concentrates: per condition (speed, pad, soil, atmosphere, tilt when given) a permutation
//     test of the between-level spread of the per-drop force NRMSE (speed: Spearman rank
//     correlation, permutation p); per stroke phase (impact onset: first 20 % of the simulated
//     stroke time, mid-stroke 20-70 %, stopping 70 % to the stop, rest after it) the phase's
//     mean squared residual over the drop's, with a sign-flip permutation p across drops.
//  3. Forward selection (diagnose_selection.h): every applicable candidate term (the library's
//     effects, and the soils' own dynamic term weakened, diagnose_fit.h CandidateTerm) is fitted
//     with zeta on top of the current model (at first the base) on the training drops, scored on
//     the held-out drops (force NRMSE) and by BIC on the training residuals. A step adds the best
//     term when all hold:
//       - it beats the current model by Delta BIC >= 10 ("very strong", Kass & Raftery 1995);
//       - parsimony: it has the fewest parameters among the step's candidates within Delta BIC < 10
//         of the best one, and it is the only one with that few (else: ambiguous, the step adds nothing);
//       - it cuts the held-out force NRMSE of the current model;
//       - it explains >= half of the current model's held-out mean-square excess over the noise
//         floor (a term that explains a small part of what remains is fitting a misfit the library
//         does not hold, e.g. a depth exponent bending towards a rigid floor);
//       - the training drops identify its parameters: none has a 95 % interval over >= 95 % of the
//         range the fit may take (a fit on one drop can put a sensor offset at its bound so).
//     Then the search starts again from the new model, until no term qualifies. The selected model
//     is named when it explains most of the gap: held-out force NRMSE falls by >= 50 % from the
//     base AND >= 80 % of the excess mean-square residual above the estimated sensor-noise floor is
//     explained. Otherwise `none`, with the residual described (what it correlates with).
//  4-5. DIR/model.yaml, DIR/diagnosis.json, DIR/report.md with plots (diagnose_report.cpp).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/util/progress.h"
#include "drop_tests/dataset/compare.h"
#include "drop_tests/gap/diagnose_fit.h"
#include "drop_tests/gap/gap_floor.h"
#include "drop_tests/gap/law_candidate.h"
#include "drop_tests/gap/sensor_inference.h"
#include "rft/enum_names.h"

namespace touchdown::gap {

// --sensor-sampling's values: "auto" (inferred) and the samplings' names.
std::vector<std::string> SensorSamplingOptionNames();

enum class DiagnoseBase { kRft, kBekker };
inline constexpr std::array<EnumName<DiagnoseBase>, 2> kDiagnoseBaseNames{
    {{DiagnoseBase::kRft, "rft"}, {DiagnoseBase::kBekker, "bekker"}}};
// The names on the command line and in Python ("rft", "bekker"), in the enum's order.
std::vector<std::string> DiagnoseBaseNames();
// The base a name stands for. Throws InputError naming `where` and `field` on any other text.
DiagnoseBase ParseDiagnoseBase(const std::string& name, const std::string& where, const std::string& field);

// The record's common offsets in time and depth (sensor_offset): fitted in every model, the base's
// included (kEveryModel, the default), or a candidate of their own that enters the model only as a
// step of the forward selection, judged as the soil's terms are (kCandidate). docs/model_gap.md
// measures both on the independent blind sets.
enum class RigOffsets { kEveryModel, kCandidate };
inline constexpr std::array<EnumName<RigOffsets>, 2> kRigOffsetsNames{
    {{RigOffsets::kEveryModel, "every"}, {RigOffsets::kCandidate, "candidate"}}};
// The names on the command line and in Python ("every", "candidate"), in the enum's order.
std::vector<std::string> RigOffsetsNames();
// The choice a name stands for. Throws InputError naming `where` and `field` on any other text.
RigOffsets ParseRigOffsets(const std::string& name, const std::string& where, const std::string& field);

struct DiagnoseOptions {
  int threads = 2;
  bool try_pairs = true;             // search again after the first term (--no-pairs: one at most)
  double min_delta_bic = 10.0;
  double min_gap_reduction = 0.5;
  double min_explained = 0.8;
  double min_step_explained = 0.5;   // of the extended model's excess, for a step to add its term
  // With a floor from replicates (gap_floor.h): the most a step's held-out improvement may be left
  // to chance (sign-flip p over the held-out drops). Where the held-out drops are too few for any
  // outcome to reach it (2^-n > max_step_p), the level is 2^-n: every held-out drop fitted better.
  double max_step_p = 0.05;
  int permutations = 2000;
  unsigned seed = 12345;             // permutation tests only
  std::optional<model::ModelFile> start_model;  // --model: starting zeta (and the file it came from)
  io::ProgressOptions progress{io::ProgressMode::kNone};  // of the candidate models fitted
  // --base: the model the effects are fitted on top of. kRft: quasi-static RFT, zeta per soil (the
  // default). kBekker: Bekker's pressure-sinkage law, n, k_c, k_phi per soil fitted on the training
  // drops (calibrate --law bekker), its moduli scaled per soil with the effects (UseBekkerBase).
  DiagnoseBase base = DiagnoseBase::kRft;
  bool law_candidate = false;        // --law-candidate: also fit and score the Bekker law (law_candidate.h)
  // --sensor-sampling: how the simulated drops are recorded to compare with the measured samples.
  // By default (nullopt) inferred from the data (sensor_inference.h: the sampling, an anti-alias
  // low-pass, a ringing load cell); given, the mean over each sample period or the value at each
  // sample time, as an override (docs/model_gap.md, "The sensor is part of the model").
  std::optional<pad::SensorSampling> sensor_sampling;
  // Per-drop nuisances (diagnose_fit.h: strength, speed, touchdown time) in every fit.
  bool drop_nuisances = true;
  // Each training drop's nuisances fitted again alone after every full fit (FitProblem::
  // refit_drop_nuisances); false (--no-refit-drops): the joint descent's, as the release before.
  bool refit_drops = true;
  // The replicates' floor read from the best-fitting candidate's residuals too, the lowest kept
  // (gap_floor.h LowerFloorByCandidates); false (--floor-from-base): from the base's alone.
  bool floor_from_best_model = true;
  // With a floor from replicates: no further term once the model's held-out mean square lies
  // within the floor's 95 % upper bound (what is left, the replicates cannot tell from their
  // scatter; the rule the selected model is named by). false (--search-within-floor): search on.
  bool stop_within_floor = true;
  // --rig-offsets: the record's common offsets in every model or as a candidate (RigOffsets).
  RigOffsets rig_offsets = RigOffsets::kEveryModel;
  // Each drop's two samples either side of its measured stop left out of its force residuals
  // (diagnose_fit.h StopSamples) where the per-drop nuisances are on (diagnose_fit.h
  // CountStopSamples says why not elsewhere); false (--count-stop-samples): every sample counts.
  bool skip_stop_samples = true;
  // --fit-on: the drop ids every model is fitted on; every other drop is held out and predicted.
  // Empty: the split by speed above. Each id must be in the dataset, every soil needs one, and at
  // least one drop must be left to predict (InputError otherwise).
  std::vector<std::string> fit_on;
};

struct DropGap {
  std::string drop_id;
  bool held_out = false;
  double force_nrmse = 0.0;
  double force_nrmse_penetration = 0.0;  // NaN when undefined
  double final_penetration_rel_error = 0.0;
  double peak_force_rel_error = 0.0;
  double noise_nrmse = 0.0;   // estimated sensor-noise floor of force_nrmse
  double force_bias = 0.0;    // mean (F_sim - F_meas) / max F_meas over the stroke (+: model too stiff)
  std::vector<double> phase_ms;  // mean squared normalised force residual per phase (4)
  // (F_sim - F) / max F at every sample from touchdown on: replicates' residuals compared
  // sample by sample (gap_floor.h).
  std::vector<double> force_residual;
  double overall_ms = 0.0;
  bool failed = false;
};

struct GapSummary {  // held-out means
  double force_nrmse = 0.0, force_nrmse_penetration = 0.0, final_penetration_rel_error = 0.0,
         peak_force_rel_error = 0.0, noise_nrmse = 0.0, mean_square = 0.0, noise_mean_square = 0.0;
};

// What a "where" finding is about: a condition of the drops (speed, pad, ...) or a phase of the
// stroke (impact onset, ...).
enum class FindingKind { kCondition, kPhase };
inline constexpr std::array<EnumName<FindingKind>, 2> kFindingKindNames{
    {{FindingKind::kCondition, "condition"}, {FindingKind::kPhase, "phase"}}};
const char* FindingKindName(FindingKind kind);

struct Finding {  // one line of "where"
  FindingKind kind = FindingKind::kCondition;
  std::string factor;  // speed, pad, ..., impact_onset, ...
  std::string summary;
  double statistic = 0.0;
  double p_value = 1.0;
  bool significant = false;
};

struct CandidateScore {
  std::vector<std::string> effect_ids;
  std::string name;  // ids joined by '+'
  bool applies = true;
  std::string why_not;
  // Ranked below the step's best few by a screening fit (FitResult::screening): not fitted in
  // full nor scored on the held-out drops, so never chosen.
  bool screened_out = false;
  FitResult fit;
  std::vector<DropGap> gaps;
  GapSummary held_out;
  double gap_reduction = 0.0;  // 1 - held-out force NRMSE / base's
  double explained = 0.0;      // of the excess mean square above the noise floor
  double delta_bic = 0.0;      // vs the base (positive = better)
  int step = 0;                // the forward-selection step that fitted it (1: on top of the base)
  int extends = -1;            // index into Diagnosis::candidates of the model it extends, -1: the base
  double delta_bic_step = 0.0;      // vs the model it extends (positive = better)
  double step_gap_reduction = 0.0;  // 1 - held-out force NRMSE / the extended model's
  double step_explained = 0.0;      // of the extended model's excess mean square above the floor
  double step_improvement_p = 1.0;  // one-sided: the held-out drops fitted better than by the extended model
  // The smallest p the sign-flip test can give on those drops (2^-n for n drops): with 4 or fewer it
  // lies above max_step_p, and the step then asks that every held-out drop fit better.
  double step_improvement_p_min = 1.0;
};

struct Diagnosis {
  std::string dataset_dir;
  std::vector<bool> held_out;
  std::vector<std::string> fit_on;  // DiagnoseOptions::fit_on: the designated training drops, or empty
  FitProblem problem;
  // Per-drop nuisances asked for but off: the drops repeat too few conditions (kMinNuisanceDf).
  bool nuisances_without_replicates = false;
  CandidateScore base;
  std::vector<CandidateScore> candidates;  // every step's, in order
  std::vector<int> selection;              // the model after each accepted step (index into candidates)
  int winner = -1;                         // index into candidates of the named model, -1: none
  std::string named_effect = "none";       // named_effects joined by '+', or none
  std::vector<std::string> named_effects;  // the soil's effects found, in the order selected
  // Nuisance terms of the rig found in the named model (sensor_offset): measurement, not the soil.
  std::vector<std::string> named_nuisances;
  SensorInference sensor;                  // the sensor model, inferred (with its evidence) or given
  GapFloor floor;                          // what the held-out gap is judged against (the base's)
  std::vector<CellLackOfFit> lack_of_fit_before, lack_of_fit_after;  // the base's and the named model's
  // When the named model weakens the soils' own dynamic term: what the data say about it, in words
  // (the term's weakening is reported there, not as an effect found). Else empty.
  std::string dynamic_term_statement;
  std::string decision;                    // why
  std::string residual_description;
  std::vector<Finding> where;
  std::vector<Finding> where_after;        // the same analysis after the named effect
  double seconds = 0.0;
  long simulations = 0;
  std::optional<LawCandidate> law_candidate;  // only with DiagnoseOptions::law_candidate
  std::vector<dataset::BekkerFit> bekker_base;  // --base bekker: the base's soils (else empty)
};

Diagnosis RunDiagnosis(const dataset::Dataset& measured, const DiagnoseOptions& options = {});
nlohmann::json DiagnosisJson(const Diagnosis& d);
// How the drops were split, in words (diagnosis.json's split.rule and the report's section 1).
std::string SplitRule(const Diagnosis& d);
// DIR (replaced when complete): model.yaml, diagnosis.json, report.md, per_drop.csv, data/,
// plots/ (PNG via gnuplot when installed, with the script).
void WriteDiagnosis(const Diagnosis& d, const dataset::Dataset& measured, const io::OutputTarget& out);
// `touchdown diagnose MEASURED --out DIR` as one call (the command and touchdown.diagnose): checks
// DIR before anything runs, reads the dataset, diagnoses and writes DIR.
Diagnosis DiagnoseToDirectory(const std::string& measured_dir, const DiagnoseOptions& options,
                              const io::OutputTarget& out);

}  // namespace touchdown::gap
