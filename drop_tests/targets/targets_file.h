#pragma once
// A targets file (TARGETS.yaml, `touchdown calibrate --targets`): published scalar results (a
// final depth, a peak force, a ratio of two of them, a lander's roll or pitch, a bound on one of
// them) and the free parameters that may move to reproduce them. Schema: docs/calibration_targets.md.
//
//   schema_version: 1
//   type: targets
//   parameters:
//     - {name: zeta_lp, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, upper: 8, start: 3.48, source: ...}
//     - {name: lambda_lp, soil: fjs1_lp, field: dynamic_lambda, lower: 0, upper: 4, start: 1.1, source: ...}
//     - {name: n_cp, soil: fjs1_cp_bekker, field: bekker.n, lower: 0.5, upper: 1.5, start: 1, source: ...}
//     - {name: curved_a1, pad: curved, field: profile.a1_per_mm, lower: 0.01, upper: 0.08, start: 0.0319, source: ...}
//     - {name: joint_radius, lander: sutoh2017_lander, field: legs.joint_radius_mm, lower: 200, upper: 400, ...}
//   targets:
//     - {name: depth, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m,
//        value: 0.02, uncertainty: 0.001, use: fit, source: ...}
//     - {name: lp_over_cp, ratio: {numerator: {campaign: {file: F, pad: flat, soil: fjs1_lp, speed_m_s: 1.0},
//        quantity: final_penetration_m}, denominator: {...}}, value: 1.9, uncertainty: 0.1, use: fit, source: ...}
//     - {name: roll_B, lander: lander_case_B, quantity: final_roll_deg, at_least: -0.5, at_most: 0.5, ...}
//
// Loading resolves every pad, soil, lander and scenario and checks every number: a bad entry throws
// InputError naming the file, the field and the value, before anything runs.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/scenario/lander_scenario_types.h"
#include "rft/gravity_constants.h"

namespace touchdown::targets {

// What a free parameter changes (always in memory: the files stay as they are).
enum class ParameterKind {
  kSoilZeta,     // zeta_N_cm3 of a soil (at the soil's reference gravity), by the soil's name
  kSoilDynamicLambda,  // dynamic_lambda of a soil whose dynamic term is on, by the soil's name
  kSoilBekker,   // bekker.n, bekker.k_c_kN_m_n1 or bekker.k_phi_kN_m_n2 of a soil whose law is bekker
  kPadField,     // a number of a pad file (a dotted path, e.g. profile.a1_per_mm)
  kLanderField,  // a number of a lander file (e.g. legs.joint_radius_mm)
};

// A Gaussian prior on a parameter (`prior: {value, sd, source}`): the fit adds the residual
// (x - value) / sd to the targets' (a maximum a posteriori fit; its covariance is the posterior's
// Laplace approximation). For a parameter the targets alone cannot fix: a literature value and
// its spread, stated with its source.
struct ParameterPrior {
  double value = 0.0;  // in the field's own unit, within [lower, upper]
  double sd = 0.0;     // one standard deviation, > 0
  std::string source;
};

struct Parameter {
  std::string name;
  ParameterKind kind = ParameterKind::kSoilZeta;
  std::string object;  // the soil, pad or lander as the file names it
  std::string file;    // its resolved file (a soil's name for the soil kinds matching: soil_name)
  std::string soil_name;  // soil kinds: the soil's name (what model files and scenarios match)
  double soil_reference_gravity_m_s2 = rft::kEarthGravity_m_s2;  // soil kinds
  std::string field;   // zeta_N_cm3, dynamic_lambda, bekker.<key>, or the dotted path in the pad or lander file
  double lower = 0.0, upper = 0.0, start = 0.0;  // in the field's own unit
  std::string source;
  std::optional<ParameterPrior> prior;
  std::string Address() const;  // e.g. "pad curved: profile.a1_per_mm"
  const model::BekkerOverrideField* bekker = nullptr;  // kSoilBekker: which of the three
  bool IsSoil() const {
    return kind == ParameterKind::kSoilZeta || kind == ParameterKind::kSoilDynamicLambda || kind == ParameterKind::kSoilBekker;
  }
};

enum class Quantity {
  kFinalPenetration,  // drop: final_penetration_m
  kPeakForce,         // drop: peak_force_N
  kTimeToRest,        // drop: time_to_rest_s
  kFinalRoll,         // lander: final_roll_deg
  kFinalPitch,        // lander: final_pitch_deg
  kMaxTilt,           // lander: max_tilt_deg
  kPadDepth,          // lander: pad_depth_m (one pad's final penetration; `pad: 1..4`)
  kPadDepthSpread,    // lander: pad_depth_spread (deepest pad's depth / shallowest's)
};
const char* QuantityName(Quantity q);
bool IsLanderQuantity(Quantity q);

// A scenario a target runs: a rig drop, a row of a campaign file, or a lander scenario file.
struct ScenarioRun {
  enum class Kind { kDrop, kCampaign, kLander } kind = Kind::kDrop;
  std::string label;  // e.g. "drop flat/fjs1_lp 1 m/s", "lander lander_case_B"
  // drops and campaign rows
  std::shared_ptr<const io::PadSpec> pad;
  rft::SoilParameters soil;
  drop::DropConditions conditions;
  // landers
  std::shared_ptr<const scenario::LanderScenario> lander;
};

struct Measure {
  size_t scenario = 0;  // index into TargetsFile::scenarios
  Quantity quantity = Quantity::kFinalPenetration;
  int pad = 0;  // kPadDepth: 1..4
};

struct Target {
  std::string name;
  Measure measure;
  std::optional<Measure> denominator;  // a ratio of two measures
  std::optional<double> value, at_most, at_least;  // a value, or one or two bounds
  double uncertainty = 0.0;
  bool fit = true;  // use: fit (else predict: reported, not fitted)
  std::string source;
  std::string Describe(const std::vector<ScenarioRun>& scenarios) const;
};

struct FitSettings {
  double relative_step = 1e-3;  // central differences: step = relative_step * |value|
  int max_iterations = 50;
  double confidence = 0.95;     // of the reported intervals
};

struct TargetsFile {
  std::string source;
  std::string name;
  std::string description;
  std::vector<Parameter> parameters;
  std::vector<Target> targets;
  std::vector<ScenarioRun> scenarios;  // each distinct scenario once, shared by the targets naming it
  FitSettings settings;
};

TargetsFile LoadTargetsFile(const std::string& path);
// The reference of a targets file's keys (schema_doc.h; `touchdown schema`, docs/reference.md).
std::vector<io::BlockDoc> TargetsFileSchema();
// A file's path as Parameter::file holds it (weakly canonical), so that a file compares equal to
// itself however a scenario or targets file names it.
std::string Canonical(const std::string& path);

}  // namespace touchdown::targets
