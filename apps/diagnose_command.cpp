// touchdown diagnose MEASURED_DIR [--model MODEL.yaml] --out DIR: the model-gap workflow
// (drop_tests/gap/diagnose.h, docs/model_gap.md).
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/util/work_pool.h"
#include "drop_tests/gap/diagnose.h"
#include "rft/physical_limits.h"

namespace touchdown::app {

namespace {
struct DiagnoseArgs {
  std::string measured, model, out, base = "rft", sensor_sampling = "auto";
  int threads = 0;
  double min_step_explained = gap::DiagnoseOptions{}.min_step_explained;
  std::vector<std::string> fit_on;
  bool no_pairs = false, law_candidate = false, no_drop_nuisances = false, floor_from_base = false,
       count_stop_samples = false, search_within_floor = false, no_refit_drops = false;
  std::string rig_offsets = "every";
};
}  // namespace

void AddDiagnoseCommand(CLI::App& app) {
  auto args = std::make_shared<DiagnoseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "diagnose", "Find where simulation and measurement disagree, name the missing effect, show the gap shrink");
  cmd->add_option("measured", args->measured, "measured dataset directory (drops.csv + traces)")->required();
  cmd->add_option("--model", args->model, "model file whose zeta per soil starts the calibration");
  cmd->add_option("--out", args->out, "output directory: new, empty, or an earlier output of this command (replaced whole when complete)")->required()->check(NonEmptyPath());
  cmd->add_option("--threads", args->threads, "threads (default: all cores)")
      ->check(NumberIn(0, limits::kMaxThreads));
  cmd->add_flag("--no-pairs", args->no_pairs, "name one term at most (no search again after the first, docs/model_gap.md)");
  cmd->add_option("--min-step-explained", args->min_step_explained,
                  "share of the held-out excess over the noise floor, left by the model so far, that a term must "
                  "explain to be added (default 0.5; 0: the rule before it, docs/model_gap.md)")
      ->check(NumberIn(0.0, 1.0));
  cmd->add_option("--fit-on", args->fit_on,
                  "drop ids (comma-separated or repeated) every model is fitted on; every other drop is held out and "
                  "predicted (default: every third drop by speed is held out, docs/model_gap.md)")
      ->delimiter(',');
  cmd->add_option("--base", args->base,
                  "the model the effects are fitted on: rft (zeta per soil, default) or bekker (n, k_c, k_phi per "
                  "soil fitted as calibrate --law bekker; docs/bekker_soil.md)")
      ->check(CLI::IsMember(gap::DiagnoseBaseNames()));
  cmd->add_flag("--law-candidate", args->law_candidate,
                "also fit the Bekker law per soil on the training drops and score it (docs/bekker_soil.md)");
  cmd->add_option("--sensor-sampling", args->sensor_sampling,
                  "how the measured drops were sampled: auto (default: inferred from the data, with an anti-alias "
                  "low-pass and a ringing load cell among the candidates), or, as an override, period_mean (the "
                  "mean over each sample period) or instantaneous (the value at each sample time); docs/model_gap.md")
      ->check(CLI::IsMember(gap::SensorSamplingOptionNames()));
  cmd->add_flag("--no-drop-nuisances", args->no_drop_nuisances,
                "fit every drop at its nominal strength, speed and touchdown time (the workflow before per-drop "
                "scatter was modelled; docs/model_gap.md)");
  cmd->add_flag("--no-refit-drops", args->no_refit_drops,
                "keep each training drop's nuisances where the joint fit left them, as the release before (by "
                "default each is fitted again alone from a fresh scan of its touchdown time after every full fit; "
                "docs/model_gap.md)");
  cmd->add_flag("--floor-from-base", args->floor_from_base,
                "read the replicates' floor from the base model's residuals alone, as the release before (by "
                "default it is read from each fully fitted candidate's too and the lowest kept; docs/model_gap.md)");
  cmd->add_flag("--count-stop-samples", args->count_stop_samples,
                "count the two samples either side of each drop's measured stop in its force residual, as the "
                "release before (by default they are left out; docs/model_gap.md)");
  cmd->add_flag("--search-within-floor", args->search_within_floor,
                "search for a further term after a model whose held-out gap lies within the replicates' floor's "
                "95 % upper bound, as the release before (by default the search stops there; docs/model_gap.md)");
  cmd->add_option("--rig-offsets", args->rig_offsets,
                  "the record's common offsets in time and depth: every (fitted in every model, default) or "
                  "candidate (added only as a step of the selection, judged as the soil's terms; docs/model_gap.md)")
      ->check(CLI::IsMember(gap::RigOffsetsNames()));
  cmd->callback([args] {
    gap::DiagnoseOptions o;
    o.rig_offsets = gap::ParseRigOffsets(args->rig_offsets, "command line", "--rig-offsets");
    o.stop_within_floor = !args->search_within_floor;
    o.drop_nuisances = !args->no_drop_nuisances;
    o.refit_drops = !args->no_refit_drops;
    o.floor_from_best_model = !args->floor_from_base;
    o.skip_stop_samples = !args->count_stop_samples;
    o.threads = io::ThreadsFor(args->threads);
    o.try_pairs = !args->no_pairs;
    o.min_step_explained = args->min_step_explained;
    o.progress.mode = io::ProgressMode::kAuto;
    o.law_candidate = args->law_candidate;
    o.fit_on = args->fit_on;
    o.base = gap::ParseDiagnoseBase(args->base, "command line", "--base");
    o.sensor_sampling = dataset::ParseSensorSampling(args->sensor_sampling);  // nullopt: auto (checked by IsMember)
    if (!args->model.empty()) o.start_model = model::LoadModelFile(args->model);
    const gap::Diagnosis d = gap::DiagnoseToDirectory(args->measured, o, {args->out, {args->measured, args->model}});
    const nlohmann::json j = gap::DiagnosisJson(d);
    nlohmann::json summary{{"named_effect", j["named_effect"]},     {"named_effects", j["named_effects"]},
                           {"selected_terms", j["selected_terms"]}, {"decision", j["decision"]},
                           {"gap_before", j["gap_before"]["force_nrmse"]}, {"gap_after", j["gap_after"]["force_nrmse"]},
                           {"gap_reduction", j["gap_reduction"]}, {"seconds", j["seconds"]},
                           {"out", args->out}};
    if (j.contains("dynamic_term_statement")) summary["dynamic_term_statement"] = j["dynamic_term_statement"];
    std::cout << summary.dump(2) << std::endl;
  });
}

}  // namespace touchdown::app
