#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "drop_tests/output_path.h"
#include "drop_tests/sweep.h"
#include "drop_tests/sweep_mpi.h"
#include "rft/input_error.h"

namespace touchdown::app {

namespace {
struct SweepArgs {
  std::string sweep, out, shard, model, progress = "auto";
  int threads = 0;
  int batch = 512;
  double max_drop_wall_time_s = 0.0;  // only when given; else the sweep file's (default 60 s)
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
  CLI::Option* max_wall =
      cmd->add_option("--max-drop-wall-time", args->max_drop_wall_time_s,
                      "wall-clock limit per drop in seconds, 0 = none (default: the sweep file's "
                      "max_drop_wall_time_s, else 60); a drop over it is recorded as failed");
  cmd->callback([args, max_wall] {
    const bool max_wall_given = max_wall->count() > 0;
    if (max_wall_given && !(std::isfinite(args->max_drop_wall_time_s) && args->max_drop_wall_time_s >= 0.0))
      throw InputError("--max-drop-wall-time: must be a finite number of seconds >= 0 (0: no limit)");
    drop::SweepRunOptions options;
    options.threads = args->threads;
    if (!args->shard.empty()) options.shard = drop::ParseShard(args->shard);
    options.batch_size = static_cast<size_t>(args->batch);
    options.progress = args->progress == "bar"     ? drop::ProgressMode::kBar
                       : args->progress == "lines" ? drop::ProgressMode::kLines
                       : args->progress == "none"  ? drop::ProgressMode::kNone
                                                   : drop::ProgressMode::kAuto;
    drop::SweepPlan plan = drop::LoadSweepPlan(args->sweep, args->model);
    if (max_wall_given) plan.rig.integrator.max_wall_time_s = args->max_drop_wall_time_s;
    drop::OpenOutputDirectory({args->out, {args->sweep, args->model}}, drop::OutputKind::kSweep);
    int rank = 0;
    const drop::SweepRunSummary s = drop::LaunchedByMpirun() ? drop::RunSweepMpi(plan, args->out, options, &rank)
                                                             : drop::RunSweep(plan, args->out, options);
    if (rank != 0) return;
    std::cout << "sweep " << plan.name << ": " << s.in_shard << " drops"
              << (options.shard.count > 1 ? " in shard " + options.shard.Text() : std::string()) << " of "
              << s.total << "; " << s.already_done << " already done, " << s.computed << " run now on " << s.ranks
              << " rank(s) x " << s.threads << " thread(s) in " << std::fixed << std::setprecision(2) << s.seconds
              << " s (" << std::setprecision(0) << (s.seconds > 0 ? s.computed / s.seconds : 0.0) << " drops/s); "
              << s.failed << " failed\nwrote " << drop::ResultsDbPath(args->out) << "\n";
  });
}

}  // namespace touchdown::app
