#pragma once
// What a stability study runs after its landings (docs/stability_studies.md, "Follow-ups"):
//
//   Re-checks. The landings whose outcome could flip (tipped over, or a max tilt within
//   `tilt_margin_deg` of the standing lander's tip-over angle; with `unsettled: true` also every
//   landing that ended unsettled) run again with the reference model,
//   the study's lander at a tighter integrator tolerance (study.recheck.rtol) with its pads meshed
//   as their file says (a scenario's pad_angular_segments is a fast model's), so the published
//   P(tip), percentiles and worst cases are the reference model's.
//
//   Soil pairing. A study that draws its soils runs its landings again with every soil at its
//   calibration's best values, re-checked alike (soil_pairing.h).
//
//   Joint-range sensitivity. When the pads reach their ball joints' stops (a swing beyond the cone
//   limit's half angle) in more than 5 % of the landings, K of them run again with every joint's
//   half angle x0.5 and x1.5 (stiffness and damping unchanged): P(tip) on those K landings at the
//   three ranges says how much the answer hangs on the range. Of the K, only the landings that could
//   tip over at another range run again (MayTipAtAnotherRange: tipped, unsettled, failed, or a max
//   tilt within `screen_margin_deg` of the tip-over angle); the others keep the study's outcome.
//
// Each follow-up is a plan derived from the study's (its `variant` names the change, so its
// database is never mixed up with the study's) run by the sweep engine with a list of the drops
// to run (SweepRunOptions::indices) into a subdirectory of the study's: DIR/recheck/,
// DIR/joint_range_x0.5/, DIR/joint_range_x1.5/. A drop keeps its study index (the same landing),
// so the analysis matches records by index; a kill resumes; results are bit-identical for any
// number of threads.
#include <cstdint>
#include <iosfwd>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/stability/soil_pairing.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_statistics.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"

namespace touchdown::stability {

// The fraction of the completed landings above which the joint-range sensitivity runs.
inline constexpr double kJointRangeTrigger = 0.05;
// The factors of the half angle the sensitivity runs at (1 is the study itself).
inline constexpr double kJointRangeFactors[2] = {0.5, 1.5};

// The smallest static tip-over angle of the lander standing level [deg]: over the four edges of
// its support polygon (lander::EdgeTippings, joint centres as pivots), the rotation that brings
// the centre of mass over an edge. The smallest over the plan's pads when the study varies them.
double StandingTipAngleDeg(const sweep::SweepPlan& plan);

// Whether a completed landing's outcome could flip under the reference model: it tipped over, or
// its max tilt came within `s.tilt_margin_deg` of `tip_angle_deg`, or (with `s.unsettled`) it ended
// unsettled (neither at rest nor tipped over). A failed landing has no outcome to check.
bool NeedsRecheck(const sweep::DropRecord& r, double tip_angle_deg, const RecheckSettings& s);

// A landing reached its joints' stops: a pad swung further than the cone's half angle.
bool ReachedStops(const sweep::DropRecord& r, double half_angle_deg);

// Whether the joint-range sensitivity runs a landing again at another range: always without a
// screen (`s.screen_margin_deg` unset); else when the study's landing failed, tipped over, ended
// unsettled, or its max tilt came within the screen's margin of `tip_angle_deg`. A landing left out
// stood, settled, that far below the tip-over angle; the range moves max tilts by a few degrees
// there (study.h, kDefaultJointRangeScreenDeg), so it keeps the study's outcome.
bool MayTipAtAnotherRange(const sweep::DropRecord& r, double tip_angle_deg, const JointRangeSettings& s);

// The study's plan with the reference model (the re-checks') / every joint's half angle x factor.
sweep::SweepPlan RecheckPlan(const Study& study);
sweep::SweepPlan JointRangePlan(const Study& study, double factor);
// The half angle of the lander's joint stops [deg]; NaN without a cone limit (the smallest over
// the legs when they differ).
double ConeHalfAngleDeg(const sweep::SweepPlan& plan);
// K of a study's N landings spread evenly over its indices (floor(j N / K), j < K): all of them when
// K = N, and a random study's sample of size K otherwise (each of its landings is an independent draw).
std::vector<int64_t> SpreadIndices(int64_t n, int64_t k);
// The K landings the sensitivity runs: K = min(settings' samples, the study's landings), spread.
std::vector<int64_t> JointRangeIndices(const Study& study);

// Subdirectories of the study's directory the follow-ups write.
std::string RecheckDir(const std::string& out_dir);
std::string JointRangeDir(const std::string& out_dir, double factor);

struct RecheckReport {
  bool enabled = true;
  double rtol = 0.0, tip_angle_deg = 0.0, margin_deg = 0.0;
  bool unsettled = false;  // every unsettled landing re-checked too (RecheckSettings::unsettled)
  // Rim segments of the study's (fast) pads and of the reference model's (the pad file's); 0: a
  // meshed pad.
  int fast_pad_angular_segments = 0, reference_pad_angular_segments = 0;
  int64_t rechecked = 0;        // landings run again with the reference model
  int64_t outcome_changed = 0;  // of them, tipped over under one model and not the other
  std::vector<std::string> changed_landings;  // their drop ids, in index order
  int64_t reference_failed = 0;  // the reference run failed: the fast record is kept
  std::vector<std::string> reference_failed_landings;
  double largest_max_tilt_change_deg = 0.0;  // |fast - reference| over the re-checked landings
};

struct JointRangeVariant {
  double factor = 1.0;
  double half_angle_deg = 0.0;
  int64_t landings = 0, tipped = 0, failed = 0;  // of the K (failed: not counted)
  double probability = 0.0;  // NaN without landings
  BinomialInterval interval;
  int64_t differs_from_study = 0;  // landings (completed in both) whose tip-over differs from x1
};

struct JointRangeReport {
  bool cone_limit = false;  // the lander has one (without it there is no range to vary)
  double half_angle_deg = 0.0;
  int64_t at_stops = 0, landings = 0;  // completed landings (after re-checks) that reached the stops
  double at_stops_fraction = 0.0;
  bool enabled = true;  // not `joint_range_sensitivity: none`
  bool ran = false;
  std::string reason;   // why it did not run
  int64_t samples = 0;  // K
  // The screen (MayTipAtAnotherRange): its margin (unset: none, all K run), the tip-over angle it
  // counts from, and how many of the K ran at x0.5 and x1.5 (the others: the study's records).
  std::optional<double> screen_margin_deg;
  double tip_angle_deg = 0.0;
  int64_t screened_in = 0;
  std::vector<JointRangeVariant> variants;  // x0.5, x1 (the study's records), x1.5
};

struct StudyFollowUps {
  RecheckReport recheck;
  JointRangeReport joint_range;
  std::optional<SoilPairingReport> soil_pairing;  // a study with soil_uncertainty
  std::vector<sweep::DropRecord> records;  // the study's, the re-checked ones replaced by the reference's
  std::vector<sweep::DropRecord> fast;     // the fast records of the re-checked landings
  int stop_signal = 0;                     // a follow-up stopped by it: no analysis
  int64_t computed = 0, already_done = 0;  // landings of the follow-ups run now / found stored
};

// Runs the follow-ups of a study whose landings `records` (complete, index order) are done, each a
// sweep into its subdirectory of `out_dir` (resumed when present), on `options`' threads with its
// progress and stop flag (a shard or an index list in `options` is ignored: the follow-ups run
// whole on this process); `say`, when given, gets a line before each follow-up runs.
StudyFollowUps RunStudyFollowUps(const Study& study, std::vector<sweep::DropRecord> records,
                                 const std::string& out_dir, const sweep::SweepRunOptions& options,
                                 std::ostream* say = nullptr);

// The follow-ups' entries of summary.json ("recheck", "joint_range_sensitivity").
nlohmann::json RecheckJson(const RecheckReport& r);
nlohmann::json JointRangeJson(const JointRangeReport& j);

// The re-checks' report, and the records with the reference ones in place (pure: tests use it).
RecheckReport ApplyRechecks(const Study& study, double tip_angle_deg, std::vector<sweep::DropRecord>& records,
                            const std::vector<sweep::DropRecord>& reference, std::vector<sweep::DropRecord>* fast);

}  // namespace touchdown::stability
