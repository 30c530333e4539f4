#pragma once
// Forward selection of `touchdown diagnose` (diagnose.h, step 3): from the base, add the best
// candidate term while it beats the current model by Delta BIC >= min_delta_bic, is the only
// simplest one among those the data cannot tell from the best (parsimony), cuts the held-out force
// NRMSE of the current model, explains >= min_step_explained of its held-out excess over the
// noise floor and has its parameters identified (no 95 % interval over >= 95 % of a parameter's
// range); then search again from the new model. The selected model is
// named when it explains most of the base's gap (min_gap_reduction, min_explained).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/gap/diagnose.h"
#include "drop_tests/util/progress.h"

namespace touchdown::gap {

// Fits and scores the model of terms `ids` (held-out gaps included), seeded by `start`.
using ScoreModel = std::function<CandidateScore(const std::vector<std::string>& ids, const FitResult& start)>;
// A screening fit of the model of terms `ids` from `start` (FitCandidate's screen_iterations), or
// nullopt when the model does not apply.
using ScreenModel = std::function<std::optional<FitResult>(const std::vector<std::string>& ids, const FitResult& start)>;

// Each step screens its candidates and fits in full and scores only the kFullyScored best by the
// screening BIC (all when there are no more, or when `screen` is empty).
// Four Levenberg-Marquardt iterations from the extended model's optimum take a candidate most of
// the way: its added term's first steps carry nearly all of its gain (measured on the independent
// blind sets, docs/model_gap.md).
inline constexpr int kFullyScored = 3;
inline constexpr int kScreenIterations = 4;
// Fewer training drops, and every candidate is fitted in full (`screen` empty): the full fits are
// cheap there, and a screening fit on few drops ranks poorly (fitted on the four drops of one
// speed, the unit test's hidden dynamic term was screened out and rate damping named first).
inline constexpr int kMinTrainingDropsScreened = 12;

// Fills d.candidates (every step's, with step, extends, delta_bic_step and step_gap_reduction;
// step_explained; gap_reduction, explained and delta_bic against d.base), d.selection, d.winner, d.named_effect(s),
// d.dynamic_term_statement and d.decision. d.base must be scored.
void SelectForward(Diagnosis& d, const DiagnoseOptions& options, const ScoreModel& score, const ScreenModel& screen,
                   io::Progress& progress);

// The plain statement on the soils' own dynamic term when `model` weakens it (else empty): "the
// data do not support the shipped default's dynamic term (lambda fitted X [lo, hi] against the
// shipped L)" when the fitted lambda is significantly below the shipped one or near zero.
std::string DynamicTermStatement(const FitProblem& problem, const CandidateScore& model);

}  // namespace touchdown::gap
