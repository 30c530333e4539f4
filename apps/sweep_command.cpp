#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_mpi.h"
#include "drop_tests/sweep/sweep_stop.h"
#include "rft/input_error.h"

namespace touchdown::app {

namespace {
struct SweepArgs {
  std::string sweep, out, shard, model, progress = "auto";
  int threads = 0;
  int batch = 512;
  double max_drop_wall_time_s = 0.0;  // only when given; else the sweep file's (default: none)
  double max_drop_evaluations = 0.0;  // only when given; else the sweep file's
};
}  // namespace

void AddSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Run a sweep of drops (grids, random samples) into DIR/results.sqlite; restartable; threads, MPI, shards");
  cmd->add_option("sweep", args->sweep, "sweep YAML (e.g. data/sweeps/pad_trade.yaml)")->required();
  cmd->add_option("--out", args->out, "output directory; a restart with the same command finishes the missing drops")
      ->required();
  cmd->add_option("--threads", args->threads, "worker threads per process (default: every core)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--shard", args->shard, "I/N: run only drops with index mod N == I (job arrays; combine with merge)");
  cmd->add_option("--model", args->model, "model file (MODEL.yaml) with per-soil zeta overrides");
  cmd->add_option("--progress", args->progress, "auto (bar on a terminal, else lines), bar, lines or none")
      ->check(CLI::IsMember({"auto", "bar", "lines", "none"}));
  cmd->add_option("--batch", args->batch, "drops per database transaction (default 512)")
      ->check(CLI::Range(1, 1000000));  // a bounded range: CLI::PositiveNumber prints DBL_MAX as its range
  CLI::Option* max_evaluations = cmd->add_option(
      "--max-drop-evaluations", args->max_drop_evaluations,
      "work limit per drop: right-hand-side evaluations of its integrator, 0 = none (default: the sweep file's "
      "max_drop_evaluations, else " + std::to_string(sweep::kDefaultMaxDropEvaluations) +
          "); deterministic; a drop over it is recorded as failed, and retried by a rerun with a higher limit");
  CLI::Option* max_wall =
      cmd->add_option("--max-drop-wall-time", args->max_drop_wall_time_s,
                      "opt-in wall-clock limit per drop in seconds, 0 = none (default: the sweep file's "
                      "max_drop_wall_time_s, else none); which drops fail on it depends on machine load");
  cmd->callback([args, max_wall, max_evaluations] {
    const bool max_wall_given = max_wall->count() > 0;
    if (max_wall_given && !(std::isfinite(args->max_drop_wall_time_s) && args->max_drop_wall_time_s >= 0.0))
      throw InputError("--max-drop-wall-time: must be a finite number of seconds >= 0 (0: no limit), got " +
                       max_wall->as<std::string>());
    const bool max_evaluations_given = max_evaluations->count() > 0;
    const double n = args->max_drop_evaluations;
    if (max_evaluations_given && !(n >= 0.0 && n <= 1e15 && n == std::floor(n)))
      throw InputError("--max-drop-evaluations: must be a whole number between 0 (no limit) and 1e15, got " +
                       max_evaluations->as<std::string>());
    sweep::SweepRunOptions options;
    options.threads = args->threads;
    if (!args->shard.empty()) options.shard = sweep::ParseShard(args->shard);
    options.batch_size = static_cast<size_t>(args->batch);
    options.progress = args->progress == "bar"     ? sweep::ProgressMode::kBar
                       : args->progress == "lines" ? sweep::ProgressMode::kLines
                       : args->progress == "none"  ? sweep::ProgressMode::kNone
                                                   : sweep::ProgressMode::kAuto;
    sweep::SweepPlan plan = sweep::LoadSweepPlan(args->sweep, args->model);
    if (max_wall_given) plan.rig.integrator.max_wall_time_s = args->max_drop_wall_time_s;
    io::OpenOutputDirectory({args->out, {args->sweep, args->model}}, io::OutputKind::kSweep);
    if (max_evaluations_given) plan.rig.integrator.max_rhs_evaluations = static_cast<long>(n);
    // SIGINT/SIGTERM: the running drops finish and are committed; exit 128 + signal below.
    const sweep::StopOnSignals stop_on_signals;
    options.stop = &sweep::StopOnSignals::flag();
    int rank = 0;
    const sweep::SweepRunSummary s = sweep::LaunchedByMpirun() ? sweep::RunSweepMpi(plan, args->out, options, &rank)
                                                             : sweep::RunSweep(plan, args->out, options);
    if (rank != 0) {
      if (s.stop_signal != 0) std::exit(128 + s.stop_signal);
      return;
    }
    if (s.stop_signal != 0) {
      const int64_t done = s.already_done + s.computed;
      std::cout << "sweep " << plan.name << ": stopped by " << (s.stop_signal == SIGINT ? "SIGINT" : "SIGTERM")
                << " after committing the drops in flight; " << done << " of " << s.in_shard << " drops done ("
                << s.computed << " run now), " << s.failed << " failed. Run the same command again to resume.\n"
                << "wrote " << sweep::ResultsDbPath(args->out) << std::endl;
      std::exit(128 + s.stop_signal);
    }
    std::cout << "sweep " << plan.name << ": " << s.in_shard << " drops"
              << (options.shard.count > 1 ? " in shard " + options.shard.Text() : std::string()) << " of "
              << s.total << "; " << s.already_done << " already done, " << s.computed << " run now on " << s.ranks
              << " rank(s) x " << s.threads << " thread(s) in " << std::fixed << std::setprecision(2) << s.seconds
              << " s (" << std::setprecision(0) << (s.seconds > 0 ? s.computed / s.seconds : 0.0) << " drops/s); "
              << s.failed << " failed"
              << (s.retried > 0 ? "; " + std::to_string(s.retried) + " drops that had failed on a lower limit run again"
                                : std::string())
              << "\nwrote " << sweep::ResultsDbPath(args->out) << "\n";
  });
}

}  // namespace touchdown::app
