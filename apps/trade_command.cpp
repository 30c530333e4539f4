#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/command_help.h"
#include "apps/option_checks.h"
#include "apps/commands.h"
#include "drop_tests/sweep/trade_run.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::app {

namespace {
struct TradeArgs {
  std::string sweep, out, model;
  int threads = 0;
};
}  // namespace

void AddTradeCommand(CLI::App& app) {
  auto args = std::make_shared<TradeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "trade", "Footpad trade study: run a sweep, tabulate and plot penetration, peak force, conversion rate, Pareto front");
  cmd->add_option("sweep", args->sweep, "sweep: a YAML file, or a bundled one by name (pad_trade)")->required();
  cmd->add_option("--out", args->out, "output directory (results.sqlite, trade.csv, summary.json, plots/)")->required()->check(NonEmptyPath());
  cmd->add_option("--threads", args->threads, "worker threads (default: every core)")
      ->check(NumberIn(0, limits::kMaxThreads));
  cmd->add_option("--model", args->model, "model file with per-soil zeta overrides");
  cmd->callback([args] {
    args->sweep = ResolveCommandInput("trade", args->sweep);
    sweep::SweepRunOptions options;
    options.threads = args->threads;
    options.progress = sweep::ProgressMode::kAuto;  // shown once the sweep has run a second
    options.progress_quiet_s = 1.0;
    const sweep::TradeRun run = sweep::RunTrade(args->sweep, args->model, args->out, options);
    const std::vector<sweep::TradeRow>& rows = run.rows;
    const sweep::TradeLimits& limits = run.limits;
    std::cout << std::left << std::setw(12) << "pad" << std::setw(12) << "soil" << std::right << std::setw(10) << "v [m/s]"
              << std::setw(12) << "depth [mm]" << std::setw(12) << "peak F [N]" << std::setw(12) << "dE/dt [W]"
              << "  margin  pareto best\n";
    for (const sweep::TradeRow& r : rows)
      std::cout << std::left << std::setw(12) << r.pad << std::setw(12) << r.soil << std::right << std::fixed
                << std::setprecision(2) << std::setw(10) << r.impact_speed_m_s << std::setw(12)
                << r.final_penetration_m * units::kMmPerM << std::setw(12) << r.peak_force_N << std::setw(12)
                << r.mean_conversion_rate_W << std::setw(8) << std::setprecision(2) << r.margin << "  "
                << (r.pareto ? "*     " : "      ") << (r.best ? "<- best" : "") << "\n";
    int feasible = 0, front = 0;
    for (const sweep::TradeRow& r : rows) feasible += r.feasible, front += r.pareto;
    std::cout << rows.size() << " rows, " << feasible << " within the limits"
              << (limits.any() ? "" : " (the sweep file has no trade: limits)") << ", " << front << " on a front\n"
              << "wrote " << args->out << "/ (trade.csv, summary.json, plots/trade, plots/pareto as PNG and SVG)\n";
  });
}

}  // namespace touchdown::app
