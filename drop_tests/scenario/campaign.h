#pragma once
// A drop campaign: a scenario YAML lists pads x soils x impact speeds (the paper's
// single-footpad campaign ships as data/scenarios/sutoh2017_single_footpad.yaml). Loading
// resolves and validates every pad, soil and number before anything runs or is written.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/util/progress.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/scenario/paper_reading.h"

namespace touchdown::scenario {

struct CampaignCase {
  std::string drop_id;  // e.g. flat_fjs1_lp_v1.00
  // Shared by every case of the pad: a pad carries its revolved body (megabytes), which a copy per
  // case multiplied by the size of the campaign (2-3 MB a drop).
  std::shared_ptr<const io::PadSpec> pad;
  rft::SoilParameters soil;
  std::string soil_source;  // the soil's YAML file
  drop::DropConditions conditions;
};

// A ratio of one summary quantity between two cases, printed beside the paper's figures.
struct PaperCheck {
  std::string name;
  std::string quantity;  // final_penetration_m or peak_force_N
  std::string numerator_pad, numerator_soil, denominator_pad, denominator_soil;
  double speed_m_s = 0.0;
  double paper_experiment = 0.0;  // 0 when the paper gives none
  double paper_rft = 0.0;
  std::string source;
  // Whether this agreement was used to fit a parameter (then it is no evidence), and by what: a
  // targets file (docs/calibration_targets.md) or the fit named in a data file.
  bool used_for_fit = false;
  std::string fit_by;
  // The reading of an ambiguous paper sentence the paper figure rests on, if it is one.
  std::optional<PaperReading> reading;
};

struct CampaignScenario {
  std::string name;
  std::string description;
  std::string source;            // the scenario file
  double reference_speed_m_s = 0.0;  // the speed shown in the per-case plots (paper: 1.0 m/s)
  std::vector<CampaignCase> cases;
  std::vector<PaperCheck> checks;
  // A model file (MODEL.yaml: calibrated zeta, effect terms) every case runs with, as `drop
  // --model` runs one drop; the cases keep their soils as the files give them.
  std::optional<model::ModelFile> model;
  std::string model_source;
};

struct CampaignResult {
  CampaignScenario scenario;
  std::vector<drop::PadDrop> drops;  // in the order of scenario.cases (summaries only after RunCampaignToDirectory)
};

struct CheckOutcome {
  PaperCheck check;
  double simulated = 0.0;
};

// A campaign file may name a model file (`model:`, beside the file); `campaign --model` sets or
// replaces it (SetCampaignModel).
CampaignScenario LoadCampaignScenario(const std::string& path);
// The reference of a campaign scenario's keys (schema_doc.h; `touchdown schema`, docs/reference.md).
std::vector<io::BlockDoc> CampaignSchema();
void SetCampaignModel(CampaignScenario& scenario, const std::string& model_path);

// One check's entry in summary.json's paper_checks.
nlohmann::json CheckOutcomeJson(const CheckOutcome& c);
CampaignResult RunCampaign(const CampaignScenario& scenario);
std::vector<CheckOutcome> EvaluateChecks(const CampaignResult& result);
// Every case with its pad, soil and numbers as they were run (house style: resolved config). The
// files named are written for `output_dir`, the directory the file finally lives in
// (drop_tests/catalog/paths_in_outputs.h: no absolute paths of this machine).
void WriteResolvedScenario(const CampaignScenario& scenario, const std::string& path, const std::string& output_dir);
// Writes summary.csv, summary.json, traces/, plots/ and scenario_resolved.yaml into a fresh
// directory that appears at `out_dir` only when complete (replacing an older one).
void WriteCampaignOutputs(const CampaignResult& result, const io::OutputTarget& out);
// RunCampaign and WriteCampaignOutputs in one pass that streams: each drop's trace is written to
// traces/ as the drop finishes and then released, so memory holds the summaries only (a
// 10,000-drop campaign: bench/campaign_memory_bench.cpp). The drops come back without traces.
CampaignResult RunCampaignToDirectory(const CampaignScenario& scenario, const io::OutputTarget& out,
                                      const io::ProgressOptions& progress = {io::ProgressMode::kNone});

}  // namespace touchdown::scenario
