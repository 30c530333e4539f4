#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/trade.h"

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
  cmd->add_option("sweep", args->sweep, "sweep YAML (e.g. data/sweeps/pad_trade.yaml)")->required();
  cmd->add_option("--out", args->out, "output directory (results.sqlite, trade.csv, summary.json, plots/)")->required();
  cmd->add_option("--threads", args->threads, "worker threads (default: every core)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--model", args->model, "model file with per-soil zeta overrides");
  cmd->callback([args] {
    const sweep::SweepPlan plan = sweep::LoadSweepPlan(args->sweep, args->model);
    sweep::CheckTradePlan(plan);  // before anything runs or is written
    io::OpenOutputDirectory({args->out, {args->sweep, args->model}}, io::OutputKind::kSweep);
    sweep::SweepRunOptions options;
    options.threads = args->threads;
    options.progress = sweep::ProgressMode::kNone;
    sweep::RunSweep(plan, args->out, options);
    const sweep::ResultsDb db(sweep::ResultsDbPath(args->out));
    const std::vector<sweep::TradeRow> rows = sweep::TradeTable(db.ReadAll(/*with_traces=*/false));
    sweep::WriteTradeOutputs(rows, args->out);
    std::cout << std::left << std::setw(12) << "pad" << std::setw(12) << "soil" << std::right << std::setw(10) << "v [m/s]"
              << std::setw(12) << "depth [mm]" << std::setw(12) << "peak F [N]" << std::setw(12) << "dE/dt [W]"
              << "  pareto\n";
    for (const sweep::TradeRow& r : rows)
      std::cout << std::left << std::setw(12) << r.pad << std::setw(12) << r.soil << std::right << std::fixed
                << std::setprecision(2) << std::setw(10) << r.impact_speed_m_s << std::setw(12)
                << r.final_penetration_m * 1e3 << std::setw(12) << r.peak_force_N << std::setw(12)
                << r.mean_conversion_rate_W << "  " << (r.pareto ? "*" : "") << "\n";
    std::cout << "wrote " << args->out << "/ (trade.csv, summary.json, plots/trade.png, plots/pareto.png)\n";
  });
}

}  // namespace touchdown::app
