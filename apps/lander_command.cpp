#include <iostream>
#include <memory>
#include <optional>
#include <utility>
#include <nlohmann/json.hpp>

#include "apps/command_help.h"
#include "apps/commands.h"
#include "lander/integ/cvode_integrator.h"
#include "apps/option_checks.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/scenario/lander_outputs.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_setup.h"

namespace touchdown::app {

namespace {
struct LanderArgs {
  std::string scenario, out, model;
  bool no_vtk = false;
};
}  // namespace

void AddLanderCommand(CLI::App& app) {
  auto args = std::make_shared<LanderArgs>();
  CLI::App* cmd = app.add_subcommand("lander", "A four-legged lander drop with ball-jointed footpads");
  cmd->add_option("scenario", args->scenario, "lander scenario: a YAML file, or a bundled one by name (lander_case_A)")
      ->required();
  cmd->add_option("--out", args->out, "output directory (summary.json, trace.csv, events.csv, plots/, "
                                      "scenario_resolved.yaml, vtk/lander.pvd for ParaView: docs/paraview.md), "
                                      "written complete or not at all")
      ->required()->check(NonEmptyPath());
  cmd->add_option("--model", args->model,
                  "model file (MODEL.yaml): zeta per soil and every effect term in its 3D form (gas_cushion on "
                  "beds in air only; sensor_offset, a measurement effect, is not applied: summary.json's "
                  "model.effects_not_applied)");
  cmd->add_flag("--no-vtk", args->no_vtk,
                "leave out vtk/ (the ParaView series: for case A 36 MB and 1-1.5 s more; docs/paraview.md)");
  cmd->callback([args] {
    args->scenario = ResolveCommandInput("lander", args->scenario);
    const io::OutputTarget out(args->out, {args->scenario, args->model});
    io::CheckOutputDirectory(out, io::OutputKind::kLander);
    // A resolved copy is checked on the setup it builds; its landing runs on that setup, unless
    // --model changes the soils.
    std::optional<lander::LanderSetup> setup;
    scenario::LanderScenario scenario = scenario::LoadLanderScenarioWithSetup(args->scenario, setup);
    if (!args->model.empty()) {
      scenario.model = model::LoadModelFile(args->model);
      setup.reset();
    }
    const scenario::LanderRun run = [&] {
      try {
        return setup ? scenario::RunLanderScenario(scenario, std::move(*setup)) : scenario::RunLanderScenario(scenario);
      } catch (const integ::LimitExceeded& e) {  // which of the scenario's keys sets the limit
        if (e.limit() != "max_rhs_evaluations") throw;
        throw integ::LimitExceeded("lander scenario " + scenario.name + " (" + scenario.source +
                                       "): stopped at its deterministic work limit, " +
                                       std::to_string(static_cast<long long>(e.value())) +
                                       " right-hand-side evaluations (simulation.max_evaluations in the scenario; a "
                                       "stiff joint stop or a chattering contact needs many)",
                                   e.limit(), e.value());
      }
    }();
    scenario::WriteLanderOutputs(run, out, {.vtk = !args->no_vtk});
    const nlohmann::json j = scenario::LanderSummaryJson(run);
    std::cout << j.dump(2) << std::endl;
  });
}

}  // namespace touchdown::app
