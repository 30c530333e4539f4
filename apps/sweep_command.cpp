#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>

#include "apps/command_help.h"
#include "apps/commands.h"
#include "apps/option_checks.h"
#include "apps/sweep_run_flags.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_mpi.h"
#include "drop_tests/sweep/sweep_stop.h"

namespace touchdown::app {

void AddSweepCommand(CLI::App& app) {
  struct SweepArgs {
    std::string sweep, out;
    SweepRunFlags run;
  };
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Run a sweep of drops (grids, random samples) into DIR/results.sqlite; restartable; threads, MPI, shards");
  cmd->add_option("sweep", args->sweep, "sweep or study: a YAML file, or a bundled one by name (pad_trade)")->required();
  cmd->add_option("--out", args->out, "output directory; a restart with the same command finishes the missing drops")
      ->required()
      ->check(NonEmptyPath());
  AddSweepRunFlags(cmd, &args->run, "drops");
  cmd->callback([args] {
    args->sweep = ResolveCommandInput("sweep", args->sweep);
    sweep::SweepRunOptions options = RunOptionsFrom(args->run);
    sweep::SweepPlan plan = sweep::LoadSweepPlan(args->sweep, args->run.model);
    ApplyDropLimits(args->run, &plan);
    OpenSweepOutput({args->out, {args->sweep, args->run.model}}, sweep::LaunchedByMpirun());
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
