#pragma once
// A study's soil pairing (docs/stability_studies.md, "The soil's uncertainty"). A study that draws
// its soils (soil_uncertainty.h) runs its landings again with every drawn soil at its
// calibration's best values: the same index, so the same touchdown conditions. A landing's two
// outcomes then differ by the soil alone, with no model of how. This is the measure for tip-overs:
// the soil acts on them only together with conditions near the boundary, which a fit linear in
// the soil's parameters over all landings (SoilSplit) cannot see.
//
// The paired landings are a follow-up (study_followups.h) in DIR/soil_at_best_values/, re-checked
// like the study's: those whose outcome could flip run again on the reference model
// (DIR/soil_at_best_values/recheck/), so both sides of a pair are the same model's.
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_statistics.h"
#include "drop_tests/sweep/results_db.h"

namespace touchdown::stability {

// An outcome compared landing by landing, drawn soil against best values.
struct PairedOutcome {
  std::string outcome;  // tipped_over, or a metric's name (study_summary.h StudyMetrics)
  std::string unit;
  int64_t landings = 0;  // tipped_over: completed in both; a metric: stayed up in both
  double variance = 0.0;             // of the outcome with the drawn soil, over those landings
  double difference_variance = 0.0;  // of (drawn - best values)
  // difference_variance / variance: the part of the outcome's spread the soil's uncertainty makes,
  // interactions with the conditions included (0 for a constant outcome).
  double share = 0.0;
  double abs_difference_p50 = 0.0, abs_difference_p95 = 0.0, abs_difference_max = 0.0;
};

struct SoilPairingReport {
  bool enabled = true;  // not `soil_pairing: none`
  bool ran = false;
  std::string reason;   // why it did not run
  int64_t samples = 0;  // K landings paired
  int64_t landings = 0;  // of the K, completed in both
  int64_t failed = 0;    // of the K, failed in either
  int64_t tipped_drawn = 0, tipped_best = 0;  // of `landings`
  BinomialInterval interval_drawn, interval_best;
  std::vector<std::string> tipped_only_drawn, tipped_only_best;  // drop ids, index order
  int64_t rechecked = 0, recheck_changed = 0;  // best-value landings re-run on the reference model
  std::vector<PairedOutcome> outcomes;  // tipped_over first, then the metrics
};

// The study's plan with every drawn soil at its calibration's best values (every landing the same).
sweep::SweepPlan SoilAtBestValuesPlan(const Study& study);
std::string SoilPairingDir(const std::string& out_dir);
// The K landings paired: every landing, or K spread evenly (SpreadIndices).
std::vector<int64_t> SoilPairingIndices(const Study& study);

// The pairs of `indices`: the study's records (after its re-checks) against the best-value ones.
SoilPairingReport PairBySoil(const std::vector<int64_t>& indices, const std::vector<sweep::DropRecord>& study_records,
                             const std::vector<sweep::DropRecord>& at_best_values);
nlohmann::json SoilPairingJson(const SoilPairingReport& report);

}  // namespace touchdown::stability
