#pragma once
// What a stability study's landings add up to: the tip-over probability with its exact 95 %
// interval, percentiles of the landing metrics, the tip-over map, the worst cases with their
// conditions (summary.json; docs/stability_studies.md defines every entry).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_statistics.h"
#include "drop_tests/sweep/results_db.h"

namespace touchdown::stability {

// A landing metric as stored (SI, angles in degrees): name (summary.json key), unit, meaning.
struct StudyMetric {
  const char* name;
  const char* unit;
  const char* meaning;
  double (*value)(const sweep::DropRecord&);
};
// Every metric summary.json reports, in its order.
const std::vector<StudyMetric>& StudyMetrics();

struct MetricPercentiles {
  const StudyMetric* metric = nullptr;
  int64_t count = 0;  // landings with a value (NaN: none, e.g. absorber stroke without absorbers)
  double p50 = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
};

struct MapCell {
  int ix = 0, iy = 0;
  double x_low = 0.0, x_high = 0.0, y_low = 0.0, y_high = 0.0;
  int64_t landings = 0, tipped = 0;
  double probability = 0.0;  // NaN without landings
  BinomialInterval interval;
};

// A pad whose axis is more than this from the body's z axis has turned beyond edge-on [deg].
inline constexpr double kEdgeOnSwingDeg = 90.0;

// Landings whose peak axial leg load (sweep::DropRecord::peak_leg_force_N: compression, the largest
// of any leg over the trace's samples) passed the lander's stated limit: a check, the landing itself
// ran on as if every leg held.
struct LegLoadLimitCount {
  double load_limit_N = 0.0;
  int64_t over_limit = 0, tipped_or_over_limit = 0;
  BinomialInterval over_limit_interval, tipped_or_over_limit_interval;  // 95 %, Clopper-Pearson
};

struct StudySummary {
  int64_t planned = 0;   // landings in the plan
  int64_t landings = 0;  // completed (the statistics are over these)
  int64_t failed = 0;    // the solver gave up (listed by `touchdown export`; not counted)
  std::string first_failure;  // "<drop id>: <reason>" of the first failed landing, in index order
  int64_t tipped = 0;
  int64_t unsettled = 0;  // neither at rest nor tipped over at the end of the run (counted as not tipped)
  // Landings (and, of them, tip-overs) in which a pad swung past edge-on on its ball joint
  // (max_joint_swing_deg > kEdgeOnSwingDeg): their answers hang on the joints' range.
  int64_t swung_past_edge_on = 0, tipped_swung_past_edge_on = 0;
  double tip_over_probability = 0.0;  // tipped / landings; NaN without landings
  BinomialInterval interval;          // 95 %, Clopper-Pearson
  std::vector<MetricPercentiles> metrics;  // over the landings that stayed up (not tipped over)
  std::vector<MapCell> map;  // x bin major (cell ix * y bins + iy); empty without a map
  std::vector<sweep::DropRecord> worst_tilt;  // landings that stayed up with the largest max tilts, largest first
  std::vector<sweep::DropRecord> tip_overs;   // in index order, at most max_tip_over_cases
  // The tip-over margin (sweep::DropRecord::min_stability_margin_m) against the outcome: landings
  // with a margin (a database written before it has none), and those whose margin's sign
  // disagrees with their outcome (margin <= 0 and stayed up, or > 0 and tipped over), with ids.
  int64_t margin_checked = 0, margin_disagreements = 0;
  std::vector<std::string> margin_disagreeing;  // drop ids, index order, at most max_tip_over_cases
  // The follow-ups (study_followups.h) the records above include; absent: not run.
  std::optional<RecheckReport> recheck;
  std::optional<JointRangeReport> joint_range;
  // A lander whose file states legs.load_limit_N: the landings whose peak leg load passed it, and
  // those that tipped over or passed it, each with its 95 % interval (Clopper-Pearson).
  std::optional<LegLoadLimitCount> leg_load_limit;
  // A study with soil_uncertainty: the variance split and P(tip) at the soil's interval ends.
  std::optional<SoilSplit> soil_split;
  // ... and its landings paired with the same ones at the soils' best values (soil_pairing.h).
  std::optional<SoilPairingReport> soil_pairing;
};

// The value of a map axis for a landing: the plan's parameter for its index, in file units.
double MapCoordinate(const Study& study, const MapAxis& axis, int64_t index);

// Whether a landing tipped over (sweep::DropRecord::tipped_over is 1).
bool Tipped(const sweep::DropRecord& r);

// The landings over the lander's stated leg load limit (LegLoadLimitCount); none without a limit or
// for a sweep that is not a lander's.
std::optional<LegLoadLimitCount> CountOverLegLoadLimit(const Study& study, const std::vector<sweep::DropRecord>& records);
// Whether a landing completed without tipping over: the landings percentiles, exceedance curves
// and histograms describe.
bool StayedUp(const sweep::DropRecord& r);
// Whether a completed landing's tip-over margin has the sign of its outcome: <= 0 exactly when it
// tipped over. True for a landing without a margin (NaN) or one that failed: nothing to check.
bool MarginAgreesWithOutcome(const sweep::DropRecord& r);
// The summary of the landings `records` (the whole study, in index order).
StudySummary Summarise(const Study& study, const std::vector<sweep::DropRecord>& records);
nlohmann::json SummaryJson(const Study& study, const StudySummary& summary);
// A landing's conditions (every study variable) and outcome, as summary.json lists them.
nlohmann::json LandingJson(const sweep::DropRecord& r);

}  // namespace touchdown::stability
