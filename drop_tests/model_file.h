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
//       confidence: 0.95
//       fit: {method: ..., drops: 6, samples: 240, residual_rms_N: 4.1, dataset: ...}   # optional record
//   effects: {}                 # reserved: effect terms beyond quasi-static RFT (issue 6)
//   provenance: ...             # free text/mapping, kept
//
// `effects` is kept as raw YAML so that later code can read its own terms from it; until
// effect terms exist, ApplyModel refuses a model whose `effects` is not empty rather than
// silently running without them.
#include <map>
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "rft/soil.h"

namespace touchdown::drop {

struct SoilFit {
  std::string method;
  int drops = 0;
  long samples = 0;
  double residual_rms_N = 0.0;
  std::string dataset;
};

struct SoilOverride {
  double zeta_N_m3 = 0.0;                 // at reference_gravity_m_s2
  double reference_gravity_m_s2 = 9.81;
  std::optional<double> zeta_low_N_m3;    // confidence interval, both or neither
  std::optional<double> zeta_high_N_m3;
  double confidence = 0.95;
  std::optional<SoilFit> fit;
};

struct ModelFile {
  std::string source;  // the file it was read from ("" when built in memory)
  std::string name;
  std::string description;
  std::map<std::string, SoilOverride> soils;
  YAML::Node effects;     // raw; null or an empty mapping when there are none
  YAML::Node provenance;  // raw, written back unchanged

  bool HasEffects() const { return effects && effects.IsMap() && effects.size() > 0; }
};

ModelFile LoadModelFile(const std::string& path);
void WriteModelFile(const ModelFile& model, const std::string& path);
// The soil as the model sees it: its zeta replaced when the model has an override (converted to
// the soil's own reference gravity). Throws InputError if the model carries effect terms this
// build cannot apply.
rft::SoilParameters ApplyModel(const ModelFile& model, const rft::SoilParameters& soil);
// A short digest of everything ApplyModel uses, for sweep databases to detect a changed model.
std::string ModelDigestText(const ModelFile& model);

}  // namespace touchdown::drop
