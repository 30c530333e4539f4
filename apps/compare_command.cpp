#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/dataset/compare.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "rft/input_error.h"

namespace touchdown::app {

namespace {
struct CompareArgs {
  std::string measured, simulated, model, out, sensor_sampling = "period_mean";
};
}  // namespace

void AddCompareCommand(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand("compare", "Compare measured drops with simulated ones (errors, NRMSE, plots)");
  cmd->add_option("measured", args->measured, "measured dataset directory (drops.csv + traces)")->required();
  auto* sim = cmd->add_option("--simulated", args->simulated,
                              "simulated dataset directory to join on the drop conditions (default: simulate here)");
  cmd->add_option("--model", args->model, "model file to simulate with (per-soil zeta and effect terms)")->excludes(sim);
  cmd->add_option("--out", args->out, "output directory: new, empty, or an earlier output of this command (replaced whole when complete)")->required()->check(NonEmptyPath());
  cmd->add_option("--sensor-sampling", args->sensor_sampling,
                  "how the measured drops were sampled, and so the drops simulated here are recorded: period_mean "
                  "(the mean over each sample period, as an averaging load cell records; default) or instantaneous "
                  "(the value at each sample time; docs/model_gap.md)")
      ->check(CLI::IsMember(dataset::SensorSamplingNames()));
  cmd->callback([args] {
    const io::OutputTarget out(args->out, {args->measured, args->simulated, args->model});
    const dataset::Comparison c = dataset::RunComparison(args->measured, args->simulated, args->model, out,
                                                         *dataset::ParseSensorSampling(args->sensor_sampling));  // checked by IsMember
    std::cout << std::left << std::setw(24) << "drop" << std::right << std::setw(14) << "depth err" << std::setw(14)
              << "peak F err" << std::setw(14) << "NRMSE(t)" << std::setw(14) << "NRMSE(d)" << "\n";
    auto pct = [](double v) {
      std::ostringstream s;
      s << std::fixed << std::setprecision(1) << 100.0 * v << " %";
      return s.str();
    };
    for (const dataset::DropComparison& d : c.drops)
      std::cout << std::left << std::setw(24) << d.drop_id << std::right << std::setw(14)
                << pct(d.final_penetration_rel_error) << std::setw(14) << pct(d.peak_force_rel_error) << std::setw(14)
                << pct(d.force_nrmse_time.value) << std::setw(14) << pct(d.force_nrmse_penetration.value) << "\n";
    auto listed = [](const std::vector<std::string>& ids) {
      std::string text;
      for (const std::string& id : ids) text += (text.empty() ? "" : ", ") + id;
      return text;
    };
    if (!c.zero_final_penetration_drops.empty())
      std::cout << "measured final penetration 0 (no depth error, left out of its mean): "
                << listed(c.zero_final_penetration_drops) << "\n";
    if (!c.zero_peak_force_drops.empty())
      std::cout << "measured peak force 0 (no peak force error or NRMSE, left out of their means): "
                << listed(c.zero_peak_force_drops) << "\n";
    std::cout << "means over " << c.final_penetration_drops_used << " (depth), " << c.peak_force_drops_used
              << " (peak F) of " << c.drops.size() << " drops\n";
    std::cout << "mean |depth err| " << pct(c.final_penetration_rel_error) << ", mean |peak F err| "
              << pct(c.peak_force_rel_error) << ", mean force NRMSE " << pct(c.force_nrmse) << " (time), "
              << pct(c.force_nrmse_penetration) << " (penetration)\nwrote " << args->out
              << "/ (summary.json, per_drop.csv, plots/)\n";
  });
}

}  // namespace touchdown::app
