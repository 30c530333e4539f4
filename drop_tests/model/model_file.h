#pragma once
// A model file (MODEL.yaml) holds what calibration learns about the soils, so `drop --model`,
// `sweep` and `compare` can run with it and `calibrate` can write it:
//
//   schema_version: 1
//   type: model
//   name: fjs1_calibrated
//   soils:                      # per-soil overrides, keyed by the soil's catalogue name
//     fjs1_lp:
//       zeta_N_cm3: 3.61        # at reference_gravity_m_s2 (zeta scales with g, see rft/soil.h)
//       reference_gravity_m_s2: 9.81
//       zeta_interval_N_cm3: [3.52, 3.70]   # optional confidence interval
//       dynamic_lambda: 1.3     # optional: replaces the soil file's dynamic_lambda
//     fjs1_cp_bekker:           # a Bekker soil: zeta_N_cm3 may be absent (the soil file's kept)
//       bekker: {n: 1.02, k_c_kN_m_n1: 0.5, k_phi_kN_m_n2: 10100}   # each optional, the soil file's keys and units
//       confidence: 0.95
//       fit: {method: ..., drops: 6, samples: 240, residual_rms_N: 4.1, dataset: ...}   # optional record
//   effects:                    # effect terms beyond quasi-static RFT (drop_tests/model/effects.h)
//     inertial_drag: {lambda: 2.1, interval_95: {lambda: [1.8, 2.4]}}
//   provenance: ...             # free text/mapping, kept
//
// `effects` is parsed and validated on load (drop_tests/model/effects_yaml.h) and written back from
// the parsed values; ModelEffectTerms gives its terms. Where they act:
//   rig drops (`drop`, `sweep`, `compare`, `calibrate`'s users): every effect, through
//     DropConditions::effects (drop_tests/drop/pad_drop.h); gas_cushion only on drops in air (the
//     drop's atmosphere: the dataset row's in `compare`, else the soil's);
//   free drops and the lander (3D contact): every physical effect, in its 3D form
//     (model::MakeContactModel, drop_tests/model/contact_model.h); gas_cushion only on soils in air;
//   sensor_offset (measurement only) never changes a simulated drop: `compare` applies it to
//     the simulated traces it compares with recorded ones (what the rig would record), and
//     `drop` reports it as not applied.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/model/effects.h"
#include "rft/physical_limits.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/schema_doc.h"
#include "rft/gravity_constants.h"
#include "rft/soil.h"
#include "rft/stress_law_3d.h"

namespace touchdown::model {

struct SoilFit {
  std::string method;
  int drops = 0;
  long samples = 0;
  double residual_rms_N = 0.0;
  std::string dataset;  // the dataset directory as the run reached it; written relative to the model file
};

struct SoilOverride {
  // At reference_gravity_m_s2. 0: none (an override that gives lambda or Bekker's fields may leave
  // zeta out; the soil file's, possibly none, is kept). A zeta a soil holds is never 0.
  double zeta_N_m3 = 0.0;
  double reference_gravity_m_s2 = rft::kEarthGravity_m_s2;
  std::optional<double> zeta_low_N_m3;    // confidence interval, both or neither
  std::optional<double> zeta_high_N_m3;
  double confidence = 0.95;
  // The soil's dynamic-term coefficient (rft/soil.h dynamic_lambda) when calibrated; none: the
  // soil file's. Acts only on a soil whose dynamic term is on.
  std::optional<double> dynamic_lambda;
  // A Bekker soil's pressure-sinkage parameters (rft/bekker_parameters.h, SI) when calibrated; each
  // none: the soil file's. They act where the soil runs on the bekker law.
  std::optional<double> bekker_n, bekker_k_c_N_m_n1, bekker_k_phi_N_m_n2;
  std::optional<SoilFit> fit;
  bool HasBekker() const { return bekker_n || bekker_k_c_N_m_n1 || bekker_k_phi_N_m_n2; }
  // Whether the override states a zeta (written and read): one it holds, or one it must hold
  // because it gives nothing else.
  bool GivesZeta() const { return zeta_N_m3 > 0.0 || (!HasBekker() && !dynamic_lambda); }
};

// The Bekker fields an override carries, in one table for the model file, `calibrate --targets`
// (`field: bekker.<key>`) and a study's drawn soil (drop_tests/stability/soil_uncertainty.h).
struct BekkerOverrideField {
  const char* key;         // in the soil file's bekker block: n, k_c_kN_m_n1, k_phi_kN_m_n2
  const char* short_name;  // n, k_c, k_phi (a calibration report's kind soil_bekker_<short_name>)
  std::string unit;        // of the file's value (from its key's suffix: "-", "kN/m^(n+1)")
  double si_per_unit;      // SI value = file value * si_per_unit
  const limits::Range* range;  // the file value's physical range
  std::optional<double> SoilOverride::*member;
};
const std::vector<BekkerOverrideField>& BekkerOverrideFields();
// The entry of `key` (n, k_c_kN_m_n1, k_phi_kN_m_n2), or null.
const BekkerOverrideField* FindBekkerOverrideField(std::string_view key);

struct ModelFile {
  std::string source;  // the file it was read from ("" when built in memory)
  std::string name;
  std::string description;
  std::map<std::string, SoilOverride> soils;
  std::vector<Effect> effects;      // in file order (SI values); none: quasi-static RFT
  EffectIntervals effect_intervals;  // per effect (may be empty), informational, written back
  std::string provenance_yaml;      // the provenance as YAML text ("" when none), written back unchanged

  bool HasEffects() const { return !effects.empty(); }
};

// The reference of a model file's keys (schema_doc.h; `touchdown schema`, docs/reference.md); the
// effects' keys are the effect library's (effects.h).
std::vector<io::BlockDoc> ModelFileSchema();
ModelFile LoadModelFile(const std::string& path);
// The first line of every model file touchdown writes: a file that starts with it may be replaced by
// the next `calibrate --out`; any other file at that path is the user's and is never overwritten.
inline constexpr const char* kModelFileMark = "# touchdown model file (written by touchdown; it may replace this file)";
// Paths in it (a fit's dataset) are written for `output_dir`, the directory the file finally lives
// in (default: the directory of the target; drop_tests/catalog/paths_in_outputs.h).
void WriteModelFile(const ModelFile& model, const io::OutputTarget& target, const std::string& output_dir = "");
// The soil as the model sees it: its zeta replaced when the model has an override (converted to
// the soil's own reference gravity; a zeta equal to the soil's own at the same reference gravity is
// kept as it is; none kept when the override has none), its dynamic_lambda and Bekker fields
// when the override has them. Effect terms are not part of the soil: see ModelEffectTerms.
rft::SoilParameters ApplyModel(const ModelFile& model, const rft::SoilParameters& soil);
// The model's effects flattened (none when `effects` is empty). Throws InputError naming the
// model file on a repeated effect or a value out of range (a model built in memory).
rft::EffectTerms ModelEffectTerms(const ModelFile& model);
// The model as a 3D run (lander) reports it: {file, effects: [ids applied], effects_not_applied:
// {id: reason}}; gas_cushion is applied on the soils in air only (said so in its entry).
nlohmann::json ModelEffectsJson(const ModelFile& model);
// A short digest of everything ApplyModel uses, for sweep databases to detect a changed model.
std::string ModelDigestText(const ModelFile& model);

}  // namespace touchdown::model
