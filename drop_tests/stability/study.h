#pragma once
// A stability study (`touchdown stability STUDY.yaml --out DIR [--samples N]`): a lander sweep
// (drop_tests/sweep/sweep_plan.h, `type: stability`) whose landings are run by the sweep engine
// into DIR/results.sqlite, plus a `study` block saying how to analyse them:
//
//   study:
//     map: {x: slope_deg, y: horizontal_speed_m_s, bins: [10, 10],   # optional
//           contours: [0.01, 0.1], max_drawn_landings: 500}           # the figure's (defaults)
//     worst_cases: 5          # the largest max tilts listed with their conditions (default 5)
//     max_tip_over_cases: 100 # tip-overs listed with their conditions, at most (default 100)
//     recheck: {rtol: 1e-8, tilt_margin_deg: 2, unsettled: false}  # or `none` (study_followups.h)
//     joint_range_sensitivity: {samples: 1000, screen_margin_deg: 20}  # or `none`; margin `none`: all K run
//     soil_uncertainty: {fjs1_cp: {calibration: FILE.json}}  # soils' zeta drawn per landing (soil_uncertainty.h)
//     soil_pairing: {samples: 4000}  # or `none`; default: every landing again at the best values (soil_pairing.h)
//
// The map's axes are two number parameters the study varies (grid or random); its range is the
// parameter's over the plan (a random parameter's [low, high], a grid's or choice's smallest and
// largest value). Schema and outputs: docs/stability_studies.md.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/stability/soil_uncertainty.h"
#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::drop {
struct RequestNaming;
}

namespace touchdown::stability {

struct MapAxis {
  sweep::SweepParam param = sweep::SweepParam::kSlope;
  double low = 0.0, high = 0.0;  // file units (deg, m/s, ...)
  int bins = 10;
};

// The map figure's default contour levels: the probabilities a lander team states its risk at
// (one in a hundred, one in ten landings), drawn where the map crosses them.
inline const std::vector<double> kDefaultMapContours = {0.01, 0.1};
// At most this many contour levels: each is a line style of its own in one key.
inline constexpr int kMaxMapContours = 5;
// The map figure draws every landing as a mark only when the study has at most this many (and its
// tip-overs only when they are at most this many): the map's frame is about 510 x 600 pixels and a
// circle about 10 across, so 500 take about a tenth of it, where the 10,000 of the shipped lunar
// study covered every cell's colour (docs/stability_studies.md, "The map figure").
inline constexpr int64_t kDefaultMaxDrawnLandings = 500;

struct StudyMap {
  MapAxis x, y;
  std::vector<double> contours = kDefaultMapContours;  // probabilities in (0, 1), increasing
  int64_t max_drawn_landings = kDefaultMaxDrawnLandings;
};

// The default margin of the re-checks' tilt criterion [deg]. Measured (2026-11-27) on the first 40
// landings of data/studies/lab_paper_lander.yaml (`--samples 40`), run at the study's rtol 1e-6 and
// at the reference's 1e-8: their max tilts differed by at most 0.087 deg (median 5e-5 deg; 39
// landings, the reference failed on one). 2 deg is 23 times that, and the floor of 2 deg keeps a
// margin where integration error is not the only doubt (docs/stability_studies.md, "Re-checks").
inline constexpr double kDefaultRecheckMarginDeg = 2.0;

// The landings near the tip-over boundary run again with the reference model, the study's lander
// at a tighter integrator tolerance (study_followups.h, docs/stability_studies.md).
struct RecheckSettings {
  bool enabled = true;
  double rtol = 1e-8;  // default; below the scenario's own rtol (a scenario at 1e-8 or tighter: its rtol / 100)
  // Landings whose max tilt came within this of the standing lander's tip-over angle are re-run.
  double tilt_margin_deg = kDefaultRecheckMarginDeg;
  // Re-run every landing that ended unsettled too, whatever its max tilt. Off by default: the
  // reference ends at the same time, so an unsettled landing clear of the margin cannot change
  // outcome unless its max tilt moves by more than the margin. Measured on the shipped lunar study
  // (10,000 landings, 2026-11-28): the 275 landings re-checked only because they were unsettled
  // moved by at most 1.69 deg of max tilt (mean 0.14), none changed outcome, and they were 77 % of
  // the re-checks' solver steps (docs/stability_studies.md, "Follow-ups").
  bool unsettled = false;
};

// The default screen of the joint-range sensitivity [deg]: of its K landings, those whose max tilt
// stayed more than this below the tip-over angle (and that stood, settled) keep the study's outcome
// at the other ranges instead of running again. Measured (2026-12-06) on the shipped lunar study's
// K = 1,000 landings, every one run at x0.5 and x1.5: among those the 20 deg screen leaves out (max
// tilt below 25.3 deg), the range raised a landing's max tilt by at most 4.9 deg, and none came
// within 15 deg of the tip-over angle; over all 1,000 the largest rise was 14.6 deg (a landing at
// 30.6 deg that tipped at x1.5). The screen changed no count of the report; it ran 125 of the 1,000
// landings, 23 % of their solver steps (docs/stability_studies.md, "Follow-ups", "The screen").
inline constexpr double kDefaultJointRangeScreenDeg = 20.0;

// When the pads reach their joints' stops in more than 5 % of the landings, K of the landings run
// again with every joint's range halved and enlarged by half (study_followups.h).
struct JointRangeSettings {
  bool enabled = true;
  int64_t samples = 1000;  // K, at most (and at most the study's landings)
  // Of the K, those that could tip over at another range run again (study_followups.h,
  // MayTipAtAnotherRange); the others keep the study's outcome. nullopt (`screen_margin_deg: none`):
  // all K run.
  std::optional<double> screen_margin_deg = kDefaultJointRangeScreenDeg;
};

// A study that draws its soils runs its landings again with every drawn soil at its calibration's
// best values, so each landing's two outcomes differ by the soil alone (soil_pairing.h).
struct SoilPairingSettings {
  bool enabled = true;
  std::optional<int64_t> samples;  // K, at most; none: every landing (flips are rare: a sample misses them)
};

struct Study {
  sweep::SweepPlan plan;           // with --samples applied
  int64_t samples_in_file = 1;     // the random block's sample count as written (1 without one)
  std::optional<int64_t> samples_override;  // --samples
  std::optional<StudyMap> map;
  int worst_cases = 5;
  int max_tip_over_cases = 100;
  RecheckSettings recheck;
  JointRangeSettings joint_range;
  // Each named soil's zeta and dynamic_lambda drawn per landing from a calibration (the plan's
  // soil_overrides_at draws them, soil_parameters_at names them for the database).
  std::optional<SoilUncertainty> soil_uncertainty;
  SoilPairingSettings soil_pairing;  // read only with soil_uncertainty
};

// The reference of a stability study's `study` block (schema_doc.h; `touchdown schema`,
// docs/reference.md); the rest of the file is a sweep's.
std::vector<io::BlockDoc> StudySchema();
// Loads and validates the study (the sweep plan, then the study block) before anything runs.
// `samples_override` (--samples N) replaces the random block's sample count; a study without a
// random block refuses it (InputError naming --samples, or as `naming` names it: the Python
// module's "touchdown.stability: samples").
Study LoadStudy(const std::string& path, const std::string& model_override = "",
                std::optional<int64_t> samples_override = std::nullopt);
Study LoadStudy(const std::string& path, const std::string& model_override, std::optional<int64_t> samples_override,
                const drop::RequestNaming& naming);

// The label of a parameter on a plot axis, with its unit: "slope [deg]", "horizontal speed [m/s]".
std::string AxisLabel(sweep::SweepParam p);

}  // namespace touchdown::stability
