#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/command_help.h"
#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/scenario/campaign.h"
#include "rft/units.h"

namespace touchdown::app {

void AddCampaignCommand(CLI::App& app) {
  auto scenario_path = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>();
  auto model = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("campaign", "Run a list of drops from a scenario YAML; write tables, traces, plots");
  cmd->add_option("scenario", *scenario_path, "campaign scenario: a YAML file, or a bundled one by name (sutoh2017_single_footpad)")
      ->required();
  cmd->add_option("--out", *out_dir, "output directory: new, empty, or an earlier campaign output (replaced whole when the run completes)")->required()->check(NonEmptyPath());
  cmd->add_option("--model", *model,
                  "model file (MODEL.yaml: calibrated zeta per soil, effect terms) for every drop, as drop --model; "
                  "replaces the campaign file's own model:")
      ->check(NonEmptyPath());
  cmd->callback([scenario_path, out_dir, model] {
    *scenario_path = ResolveCommandInput("campaign", *scenario_path);
    const io::OutputTarget out(*out_dir, {*scenario_path, *model});
    io::CheckOutputDirectory(out, io::OutputKind::kCampaign);
    scenario::CampaignScenario scenario = scenario::LoadCampaignScenario(*scenario_path);
    if (!model->empty()) scenario::SetCampaignModel(scenario, *model);
    const scenario::CampaignResult result = scenario::RunCampaignToDirectory(scenario, out, {io::ProgressMode::kAuto});  // traces streamed
    std::cout << std::left << std::setw(28) << "drop" << std::right << std::setw(12) << "depth [mm]" << std::setw(14)
              << "peak F [N]" << std::setw(14) << "t_rest [ms]" << "\n";
    for (size_t i = 0; i < result.drops.size(); ++i) {
      const auto& r = result.drops[i].result;
      std::cout << std::left << std::setw(28) << scenario.cases[i].drop_id << std::right << std::fixed
                << std::setprecision(2) << std::setw(12) << r.final_penetration_m * units::kMmPerM << std::setw(14)
                << r.peak_force_N << std::setw(14) << r.time_to_rest_s * units::kMsPerS << "\n";
    }
    for (const scenario::CheckOutcome& c : scenario::EvaluateChecks(result)) {
      std::cout << c.check.name << " at " << c.check.speed_m_s << " m/s: simulated " << std::setprecision(2)
                << c.simulated;
      if (c.check.paper_experiment > 0) std::cout << "   paper experiment " << c.check.paper_experiment;
      if (c.check.paper_rft > 0) std::cout << "   paper RFT " << c.check.paper_rft;
      std::cout << "\n";
    }
    std::cout << "wrote " << *out_dir << "/ (summary.csv, summary.json, traces/, plots/, scenario_resolved.yaml)\n";
  });
}

}  // namespace touchdown::app
